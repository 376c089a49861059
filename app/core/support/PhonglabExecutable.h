#pragma once
#include <QString>

namespace phonglab {

// The `phonglab` program a child process runs (the mesh import, grade's
// checks, the Performance dock's bench): $PHONGLAB_EXE, else this process
// when it is phonglab, else `phonglab` beside it, else the one this build
// made (tests and benchmarks run from the build tree). Empty when none exists.
QString phonglabExecutable();

} // namespace phonglab
