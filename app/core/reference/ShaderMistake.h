#pragma once
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

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
    PerFace,          // "per-face": the face's normal, not the interpolated one (flat, faceted)
    HalfwayVector,    // "halfway-vector": Blinn's N·H, H = normalize(L + V), in place of R·V
};

// One way of breaking a mistake's rule: students break a rule
// in more than one place, and each place gives an image of its own, named
// under the same key. Form 0 is the classic one (what the key alone meant
// before); the others are in MistakeForm.
struct MistakeVariant {
    ShaderMistake key = ShaderMistake::NormalMatrix;
    int form = 0;

    auto operator<=>(const MistakeVariant &) const = default;
};

// The forms beyond 0, by key.
namespace MistakeForm {
inline constexpr int NormalByModel = 1;     // normal-matrix: the model matrix alone
inline constexpr int NormalByTranspose = 2; // normal-matrix: transpose(MV), no inverse
inline constexpr int LightUnnormalized = 1; // unnormalized: L = light - P, not normalised
inline constexpr int LightByModelView = 1;  // light-space: moved by the model-view matrix
inline constexpr int LightWithW0 = 1;       // homogeneous-w: the light's position with w = 0
inline constexpr int NormalWithW1 = 2;      // homogeneous-w: N = (MV·(n, 1)).xyz
inline constexpr int Unclamped = 1;         // attenuation: min(..., 1) left out
inline constexpr int InverseSquare = 2;     // attenuation: hard-coded 1 / d²
inline constexpr int LearnOpenGl = 3;       // attenuation: hard-coded 1 / (1 + 0.09d + 0.032d²)
inline constexpr int AmbientPerLight = 1;   // ambient: Ia·ka added once per light
inline constexpr int AmbientAttenuated = 2; // ambient: Ia·ka per light, scaled by f_att
inline constexpr int BlinnExponent = 1;     // halfway-vector: with the exponent 4n
inline constexpr int FaceNormalPerFragment = 1; // per-face: per fragment with the face normal
} // namespace MistakeForm

int mistakeFormCount(ShaderMistake key);
// Every key's forms, keys in the enum's order, forms in order.
std::vector<MistakeVariant> allMistakeVariants();
// The form in a few words ("the model matrix alone"), for a report.
QString mistakeFormSummary(MistakeVariant variant);
// "normal-matrix" for form 0, else "normal-matrix/2": a name for tables and logs.
QString mistakeVariantName(MistakeVariant variant);

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
