#pragma once
#include <QString>
#include <QStringList>

#include <optional>

namespace phonglab {

// The classic mistakes of a Phong lighting shader, each a rule of the
// illumination equation broken in one way. `phonglab check` names them by
// their keys, which scripts rely on: stable, never renamed.
enum class ShaderMistake {
    NormalMatrix,    // "normal-matrix": N moved by model-view (or model), not its inverse transpose
    Unnormalized,    // "unnormalized": N not normalised in the fragment shader after interpolation
    LightSpace,      // "light-space": the light's world position used as if in camera coordinates
    HomogeneousW,    // "homogeneous-w": a point moved with w = 0 (translation lost)
    ReflectIncident, // "reflect-incident": reflect(L, N) instead of reflect(-L, N)
    ViewVector,      // "view-vector": V pointing away from the eye
    Attenuation,     // "attenuation": f_att left out
    NegativeLight,   // "negative-light": max(0, N·L) missing, so N·L < 0 darkens
    BackfaceSpecular, // "backface-specular": a highlight where N·L <= 0
    Ambient,          // "ambient": Ia·ka left out
    Gouraud,          // "gouraud": the equation evaluated per vertex and interpolated
};

QString shaderMistakeKey(ShaderMistake mistake);
std::optional<ShaderMistake> shaderMistakeFromKey(const QString &key);
QStringList shaderMistakeKeys(); // in the order of the enum

// The term of the equation a mistake breaks and the rule it breaks, in a
// sentence for the user ("the specular term: R must be reflect(-L, N), ...").
QString shaderMistakeRule(ShaderMistake mistake);
// The mistake in a few words, for a status bar ("reflect(L, N) instead of reflect(-L, N)").
QString shaderMistakeSummary(ShaderMistake mistake);

// Whether the mistake is made where the equation is evaluated at a point
// (mistakenPhongTerms() applies it); the others change what reaches that
// point (the normal, the position, the lights) or where it is evaluated.
bool isPointwiseMistake(ShaderMistake mistake);

} // namespace phonglab
