#pragma once
#include <QString>

namespace phonglab {

// How `phonglab` is called, as `phonglab --help` starts and as a usage
// error of the window's arguments or of an unknown command ends: the
// window, the window with shaders, a command. Here, below both the window
// and the commands, because both print it.
QString programSynopsis();

} // namespace phonglab
