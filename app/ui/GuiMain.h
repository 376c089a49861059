#pragma once

namespace phonglab {

// Runs the editor on the default scene; argv[1], when given, is a scene or
// mesh file then opened in the background, as File → Open does. Returns the
// process exit code.
int runGui(int argc, char **argv);

} // namespace phonglab
