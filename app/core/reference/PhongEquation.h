#pragma once
#include <QString>

#include <optional>

namespace phonglab {

// The exercise's slide writes the specular term as max(0, R·V)^n with no
// guard, so a light behind the surface can still paint a highlight; the
// shipped shaders leave the highlight out where N·L <= 0. Both are right:
// the check passes either unless one is demanded, and says which matched.
enum class PhongEquation {
    Guarded, // no highlight where N·L <= 0 (shaders/phong.frag)
    Slide,   // the slide's equation taken literally
};
QString phongEquationKey(PhongEquation equation); // "guarded", "slide"
std::optional<PhongEquation> phongEquationFromKey(const QString &key);

} // namespace phonglab
