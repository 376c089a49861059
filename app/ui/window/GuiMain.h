#pragma once
#include <QString>

namespace phonglab {

// Runs the editor on the default scene; the files on its command line, when
// given, are then opened in the background, as File → Open does. Returns the
// process exit code. `synopsis` is how phonglab is called, printed after a
// usage error of the window's arguments: main() passes the commands' own
// (cli/common/ProgramSynopsis), which the window does not know.
int runGui(int argc, char **argv, const QString &synopsis);

class MainWindow;

// The samples the view draws with (the live check draws its own copy of the
// frame single-sampled, as the exact image is).
inline constexpr int kViewportSamples = 4;

// Only the view multisamples, with `viewportSamples`; the default format
// (the shared and build contexts, any other GL surface) gets none, so that
// nothing else pays for samples (when the view was a QOpenGLWidget, samples
// in the default format made Qt compose the whole window multisampled:
// bench_frame 38 ms against 19 ms at 800x600). Call after the window is made
// and before it is shown.
void useMultisamplingInViewOnly(MainWindow &window, int viewportSamples);

} // namespace phonglab
