#include "ShaderMistake.h"

#include "core/support/EnumNames.h"

#include <QCoreApplication>
#include <array>
#include <utility>

namespace phonglab {

namespace {
constexpr std::array kKeys = {
    std::pair{ShaderMistake::NormalMatrix, "normal-matrix"},
    std::pair{ShaderMistake::Unnormalized, "unnormalized"},
    std::pair{ShaderMistake::LightSpace, "light-space"},
    std::pair{ShaderMistake::HomogeneousW, "homogeneous-w"},
    std::pair{ShaderMistake::ReflectIncident, "reflect-incident"},
    std::pair{ShaderMistake::ViewVector, "view-vector"},
    std::pair{ShaderMistake::Attenuation, "attenuation"},
    std::pair{ShaderMistake::NegativeLight, "negative-light"},
    std::pair{ShaderMistake::BackfaceSpecular, "backface-specular"},
    std::pair{ShaderMistake::Ambient, "ambient"},
    std::pair{ShaderMistake::Gouraud, "gouraud"},
    std::pair{ShaderMistake::PerFace, "per-face"},
    std::pair{ShaderMistake::HalfwayVector, "halfway-vector"},
};

constexpr std::array kRules = {
    std::pair{
        ShaderMistake::NormalMatrix,
        QT_TRANSLATE_NOOP(
            "phonglab::ShaderMistake",
            "the normal N: it must be transformed by the inverse transpose of the model-view "
            "matrix, "
            "not by the model-view or model matrix, nor by a transpose without the inverse (which "
            "bends it under non-uniform scale)")},
    std::pair{
        ShaderMistake::Unnormalized,
        QT_TRANSLATE_NOOP(
            "phonglab::ShaderMistake",
            "the normal N: it must be normalised in the fragment shader, after interpolation has "
            "shortened it (and L and V must be unit length too)")},
    std::pair{
        ShaderMistake::LightSpace,
        QT_TRANSLATE_NOOP(
            "phonglab::ShaderMistake",
            "the light vector L: the light is placed in world coordinates and must be moved into "
            "camera coordinates by the view matrix (not left as it is, nor moved by the "
            "model-view matrix) before L = light - P")},
    std::pair{
        ShaderMistake::HomogeneousW,
        QT_TRANSLATE_NOOP(
            "phonglab::ShaderMistake",
            "points and directions: a point (the position P, the light's position) is transformed "
            "with w = 1, a direction (the normal) with w = 0; a point with w = 0 loses the "
            "translation, a direction with w = 1 gains it")},
    std::pair{ShaderMistake::ReflectIncident,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                                "the specular term: R must be reflect(-L, N); reflect() takes the "
                                "incident vector, which "
                                "points from the light to the surface")},
    std::pair{ShaderMistake::ViewVector,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                                "the specular term: V must point from the surface to the eye, V = "
                                "normalize(-P) in camera "
                                "coordinates")},
    std::pair{
        ShaderMistake::Attenuation,
        QT_TRANSLATE_NOOP(
            "phonglab::ShaderMistake",
            "the attenuation f_att = min(1 / (c1 + c2·d + c3·d²), 1) must scale each light's "
            "diffuse "
            "and specular parts, with d the distance from the surface to the light, and never "
            "exceed 1")},
    std::pair{ShaderMistake::NegativeLight,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                                "the diffuse term: N·L must be clamped with max(0, N·L); a light "
                                "behind the surface adds "
                                "nothing, it does not darken")},
    std::pair{
        ShaderMistake::BackfaceSpecular,
        QT_TRANSLATE_NOOP(
            "phonglab::ShaderMistake",
            "the specular term: where N·L <= 0 the light is behind the surface and there is no "
            "highlight either")},
    std::pair{ShaderMistake::Ambient,
              QT_TRANSLATE_NOOP(
                  "phonglab::ShaderMistake",
                  "the ambient term Ia·ka must be added once, outside the sum over the lights")},
    std::pair{ShaderMistake::Gouraud,
              QT_TRANSLATE_NOOP(
                  "phonglab::ShaderMistake",
                  "where the equation is evaluated: per fragment, with the interpolated normal; "
                  "evaluated per "
                  "vertex and interpolated, highlights smear and vanish between vertices")},
    std::pair{
        ShaderMistake::PerFace,
        QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                          "which normal: the one interpolated across the face from the vertices' "
                          "normals; with each face's own normal the surface shows its facets")},
    std::pair{ShaderMistake::HalfwayVector,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                                "the specular term: Phong's is max(0, R·V)^n with R = "
                                "reflect(-L, N); Blinn's N·H with the halfway vector H = "
                                "normalize(L + V) gives a wider highlight")},
};
constexpr std::array kSummaries = {
    std::pair{ShaderMistake::NormalMatrix,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                                "N moved by the model-view matrix, not its inverse transpose")},
    std::pair{ShaderMistake::Unnormalized,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "N not normalised after interpolation")},
    std::pair{ShaderMistake::LightSpace,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                                "the light's world position used as a camera-space one")},
    std::pair{ShaderMistake::HomogeneousW,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "the position moved with w = 0")},
    std::pair{
        ShaderMistake::ReflectIncident,
        QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "reflect(L, N) instead of reflect(-L, N)")},
    std::pair{ShaderMistake::ViewVector,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "V points away from the eye")},
    std::pair{ShaderMistake::Attenuation,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "f_att missing or wrong")},
    std::pair{ShaderMistake::NegativeLight,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "N·L not clamped with max(0, ·)")},
    std::pair{ShaderMistake::BackfaceSpecular,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "a highlight where N·L <= 0")},
    std::pair{ShaderMistake::Ambient,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "Ia·ka missing or wrong")},
    std::pair{ShaderMistake::Gouraud,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "lit per vertex, not per fragment")},
    std::pair{ShaderMistake::PerFace,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                                "lit once per face with its normal (flat shading)")},
    std::pair{ShaderMistake::HalfwayVector,
              QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                                "N·H with the halfway vector in place of R·V")},
};

struct Form {
    MistakeVariant variant;
    const char *summary;
};
// Every form, form 0 of each key included (its summary is kSummaries').
constexpr std::array kForms = {
    Form{{ShaderMistake::NormalMatrix, MistakeForm::NormalByModel},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "N moved by the model matrix alone")},
    Form{{ShaderMistake::NormalMatrix, MistakeForm::NormalByTranspose},
         QT_TRANSLATE_NOOP(
             "phonglab::ShaderMistake",
             "N moved by the transpose of the model-view matrix, without the inverse")},
    Form{{ShaderMistake::Unnormalized, MistakeForm::LightUnnormalized},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "L not normalised")},
    Form{{ShaderMistake::LightSpace, MistakeForm::LightByModelView},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                           "the light moved by the model-view matrix, not the view matrix")},
    Form{{ShaderMistake::HomogeneousW, MistakeForm::LightWithW0},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "the light's position moved with w = 0")},
    Form{{ShaderMistake::HomogeneousW, MistakeForm::NormalWithW1},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "the normal, a direction, moved with w = 1")},
    Form{{ShaderMistake::Attenuation, MistakeForm::Unclamped},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "f_att not clamped with min(..., 1)")},
    Form{{ShaderMistake::Attenuation, MistakeForm::InverseSquare},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                           "f_att hard-coded as 1 / d², not the light's c1, c2, c3")},
    Form{{ShaderMistake::Attenuation, MistakeForm::LearnOpenGl},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                           "f_att hard-coded as 1 / (1 + 0.09·d + 0.032·d²), not the light's "
                           "c1, c2, c3")},
    Form{{ShaderMistake::Ambient, MistakeForm::AmbientPerLight},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake", "Ia·ka added once per light")},
    Form{{ShaderMistake::Ambient, MistakeForm::AmbientAttenuated},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                           "Ia·ka added inside the light loop, scaled by f_att")},
    Form{{ShaderMistake::PerFace, MistakeForm::FaceNormalPerFragment},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                           "lit per fragment with the face's normal (faceted shading)")},
    Form{{ShaderMistake::HalfwayVector, MistakeForm::BlinnExponent},
         QT_TRANSLATE_NOOP("phonglab::ShaderMistake",
                           "N·H with the halfway vector and the exponent 4n in place of R·V")},
};

// In the language the run speaks (core/support/Language); UTF-8 (·, ²), unlike the keys.
QString translated(const char *text)
{
    return QCoreApplication::translate("phonglab::ShaderMistake", text);
}

QString textOf(const auto &table, ShaderMistake mistake)
{
    for (const auto &[m, text] : table)
        if (m == mistake)
            return translated(text);
    return {};
}
} // namespace

QString shaderMistakeKey(ShaderMistake mistake)
{
    return enumName(kKeys, mistake);
}

std::optional<ShaderMistake> shaderMistakeFromKey(const QString &key)
{
    return enumFromName(kKeys, key);
}

QStringList shaderMistakeKeys()
{
    return enumNames(kKeys);
}

QString shaderMistakeRule(ShaderMistake mistake)
{
    return textOf(kRules, mistake);
}

QString shaderMistakeSummary(ShaderMistake mistake)
{
    return textOf(kSummaries, mistake);
}

int mistakeFormCount(ShaderMistake key)
{
    int forms = 1;
    for (const Form &f : kForms)
        forms += f.variant.key == key ? 1 : 0;
    return forms;
}

std::vector<MistakeVariant> allMistakeVariants()
{
    std::vector<MistakeVariant> out;
    for (const auto &[key, name] : kKeys)
        for (int form = 0; form < mistakeFormCount(key); ++form)
            out.push_back({key, form});
    return out;
}

QString mistakeFormSummary(MistakeVariant variant)
{
    for (const Form &f : kForms)
        if (f.variant == variant)
            return translated(f.summary);
    return shaderMistakeSummary(variant.key);
}

QString mistakeVariantName(MistakeVariant variant)
{
    const QString key = shaderMistakeKey(variant.key);
    return variant.form == 0 ? key : QStringLiteral("%1/%2").arg(key).arg(variant.form);
}

bool isPointwiseMistake(ShaderMistake mistake)
{
    switch (mistake) {
    case ShaderMistake::Unnormalized:
    case ShaderMistake::ReflectIncident:
    case ShaderMistake::ViewVector:
    case ShaderMistake::Attenuation:
    case ShaderMistake::NegativeLight:
    case ShaderMistake::BackfaceSpecular:
    case ShaderMistake::Ambient:
    case ShaderMistake::HalfwayVector: return true;
    case ShaderMistake::NormalMatrix:
    case ShaderMistake::LightSpace:
    case ShaderMistake::HomogeneousW:
    case ShaderMistake::Gouraud:
    case ShaderMistake::PerFace: return false;
    }
    return false;
}

} // namespace phonglab
