#pragma once

namespace phonglab::cli {

// phonglab check SCENE.json [--vertex FILE] [--fragment FILE] [--shading NAME]
//                [--size WxH] [--tolerance STEPS] [--json] [--diff OUT.png]
// Renders the scene with the stages `render` would choose, checks the image
// against the exact reference and names the classic mistake that explains a
// wrong one. Exit 0 when it matches; 1 when it does not, does not compile,
// or the input is bad; 2 on wrong arguments.
int runCheck(int argc, char **argv);

} // namespace phonglab::cli
