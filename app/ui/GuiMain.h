#pragma once

namespace phonglab {

// Runs the editor on the default scene; the files on its command line, when
// given, are then opened in the background, as File → Open does. Returns the
// process exit code.
int runGui(int argc, char **argv);

class MainWindow;

// Only the view multisamples, with `viewportSamples`; the window it is
// composed into gets the default format without. With samples in the
// default format Qt composes the whole window multisampled, which on
// llvmpipe doubled the presented frame (bench_frame: 38 ms against 19 ms at
// 800x600). Call after the window is made and before it is shown.
void useMultisamplingInViewOnly(MainWindow &window, int viewportSamples);

} // namespace phonglab
