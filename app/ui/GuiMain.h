#pragma once

namespace phonglab {

// Runs the editor: argv[1], when given, is the scene to open (otherwise the
// default scene). Returns the process exit code.
int runGui(int argc, char **argv);

} // namespace phonglab
