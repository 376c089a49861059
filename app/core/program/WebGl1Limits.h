#pragma once
#include <QByteArray>
#include <QString>

#include <vector>

namespace phonglab {

// What a browser refuses in a WebGL 1 shader that this driver compiles:
// ANGLE holds GLSL ES 1.00 to its appendix A, Mesa does not. A shader the
// student's browser would not run must not be checked as if it ran:
//  - no `while` and no `do` loops;
//  - a `for` loop's index starts at a constant and is compared with a
//    constant (a uniform bound, `i < uNumLights`, is refused: WebGL 1
//    courses bound the loop by a constant and `break` at the count).
// Empty for GLSL ES 3.00 and desktop GLSL, which have no such limits.
struct WebGlRefusal {
    int line = 0;    // 1-based
    int column = 0;  // 1-based, in characters
    QString message; // one translated sentence, with the browser's own words
};
std::vector<WebGlRefusal> webGl1Refusals(const QByteArray &code);

} // namespace phonglab
