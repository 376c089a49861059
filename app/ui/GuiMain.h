#pragma once

namespace phonglab {

// Runs the editor on the default scene; the files on its command line, when
// given, are then opened in the background, as File → Open does. Returns the
// process exit code.
int runGui(int argc, char **argv);

class MainWindow;

// Only the view multisamples, with `viewportSamples`; the default format
// (the shared and build contexts, any other GL surface) gets none, so that
// nothing else pays for samples (when the view was a QOpenGLWidget, samples
// in the default format made Qt compose the whole window multisampled:
// bench_frame 38 ms against 19 ms at 800x600). Call after the window is made
// and before it is shown.
void useMultisamplingInViewOnly(MainWindow &window, int viewportSamples);

} // namespace phonglab
