#include "ShaderMutations.h"

#include "TestPaths.h"
#include "render/gl/QtImages.h"

#include <QtGlobal>

namespace phonglab::test {

namespace {

ShaderSource readShipped(const QString &fileName)
{
    Result<ShaderSource> source =
        ShaderSource::fromFile(sourcePath(QStringLiteral("shaders/") + fileName));
    if (!source)
        qFatal("%s", qPrintable(source.error()));
    return std::move(*source);
}

// Replaces `from` (which must occur) by `to`, and names the result after
// the mistake so diagnostics read "reflect-incident.frag:52: ...".
void replace(ShaderSource &source, const char *from, const char *to, const QString &key);

constexpr const char *kLightCam = "vec3 lightCam = (viewMatrix * vec4(lightPosition[i], 1.0)).xyz;";
constexpr const char *kGuard = "        if (NdotL <= 0.0)\n            continue;\n";
constexpr const char *kReflected =
    "        vec3 R = reflect(-L, N);          // reflect() takes the incident "
    "vector -L\n        float RdotV = max(0.0, dot(R, V));\n";
constexpr const char *kHalfway =
    "        vec3 H = normalize(L + V);\n        float RdotV = max(0.0, dot(N, H));\n";
// The attenuation computed before the N·L guard, so that a term added with
// it is added for lights behind the surface too.
constexpr const char *kGuardWithAttenuation = "        if (NdotL <= 0.0)\n            continue;\n";
constexpr const char *kGuardAfterAttenuation =
    "        vec3 c0 = attenuation[i];\n"
    "        float f0 = min(1.0 / (c0.x + c0.y * d + c0.z * d * d), 1.0);\n"
    "        if (NdotL <= 0.0) {\n"
    "            I += f0 * Ia * ka;\n"
    "            continue;\n"
    "        }\n";

// The mistake's other forms (form 0 is withMistake(key)).
void makeForm(ShaderPair &s, MistakeVariant v, const QString &name)
{
    using K = ShaderMistake;
    namespace F = MistakeForm;
    if (v == MistakeVariant{K::NormalMatrix, F::NormalByModel}) {
        replace(s.vertex, "uniform mat3 normalMatrix;",
                "uniform mat4 modelMatrix;\nuniform mat3 normalMatrix;", name);
        replace(s.vertex, "normalCam = normalMatrix * normal;",
                "normalCam = mat3(modelMatrix) * normal;", name);
    } else if (v == MistakeVariant{K::NormalMatrix, F::NormalByTranspose}) {
        replace(s.vertex, "normalCam = normalMatrix * normal;",
                "normalCam = transpose(mat3(modelViewMatrix)) * normal;", name);
    } else if (v == MistakeVariant{K::Unnormalized, F::LightUnnormalized}) {
        replace(s.fragment, "vec3 L = toLight / d;", "vec3 L = toLight;", name);
    } else if (v == MistakeVariant{K::LightSpace, F::LightByModelView}) {
        replace(s.fragment, "uniform mat4 viewMatrix;",
                "uniform mat4 viewMatrix;\nuniform mat4 modelViewMatrix;", name);
        replace(s.fragment, kLightCam,
                "vec3 lightCam = (modelViewMatrix * vec4(lightPosition[i], 1.0)).xyz;", name);
    } else if (v == MistakeVariant{K::HomogeneousW, F::LightWithW0}) {
        replace(s.fragment, kLightCam,
                "vec3 lightCam = (viewMatrix * vec4(lightPosition[i], 0.0)).xyz;", name);
    } else if (v == MistakeVariant{K::HomogeneousW, F::NormalWithW1}) {
        replace(s.vertex, "normalCam = normalMatrix * normal;",
                "normalCam = (modelViewMatrix * vec4(normal, 1.0)).xyz;", name);
    } else if (v == MistakeVariant{K::Attenuation, F::Unclamped}) {
        replace(s.fragment, "float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);",
                "float fatt = 1.0 / (c.x + c.y * d + c.z * d * d);", name);
    } else if (v == MistakeVariant{K::Attenuation, F::InverseSquare}) {
        replace(s.fragment, "float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);",
                "float fatt = 1.0 / (d * d);", name);
    } else if (v == MistakeVariant{K::Attenuation, F::LearnOpenGl}) {
        replace(s.fragment, "float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);",
                "float fatt = 1.0 / (1.0 + 0.09 * d + 0.032 * d * d);", name);
    } else if (v == MistakeVariant{K::Ambient, F::AmbientAttenuated}) {
        replace(s.fragment, "vec3 I = Ia * ka;", "vec3 I = vec3(0.0);", name);
        replace(s.fragment, "        float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);\n",
                "        float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);\n"
                "        I += fatt * Ia * ka;\n",
                name);
        // For the lights behind the surface too, where the guarded
        // equation skips the rest (the slide's has no guard to skip).
        if (s.fragment.code.contains(kGuardWithAttenuation))
            replace(s.fragment, kGuardWithAttenuation, kGuardAfterAttenuation, name);
    } else if (v == MistakeVariant{K::HalfwayVector, F::BlinnExponent}) {
        replace(s.fragment, kReflected, kHalfway, name);
        replace(s.fragment, "pow(RdotV, shininess)", "pow(RdotV, 4.0 * shininess)", name);
    } else if (v == MistakeVariant{K::Ambient, F::AmbientPerLight}) {
        replace(s.fragment, "vec3 I = Ia * ka;", "vec3 I = vec3(0.0);", name);
        replace(s.fragment, "    for (int i = 0; i < lightCount; ++i) {\n",
                "    for (int i = 0; i < lightCount; ++i) {\n        I += Ia * ka;\n", name);
    } else {
        qFatal("no mutation for %s", qPrintable(name));
    }
}

void replace(ShaderSource &source, const char *from, const char *to, const QString &key)
{
    if (!source.code.contains(from))
        qFatal("%s: the shipped shader no longer contains \"%s\"", qPrintable(source.name), from);
    source.code.replace(from, to);
    source.name = key
        + (source.name.endsWith(QLatin1String(".vert")) ? QStringLiteral(".vert")
                                                        : QStringLiteral(".frag"));
}

// Form 0 of `mistake`, made in the shipped Phong pair `s`.
void makeKey(ShaderPair &s, ShaderMistake mistake)
{
    const QString key = shaderMistakeKey(mistake);
    switch (mistake) {
    case ShaderMistake::NormalMatrix:
        replace(s.vertex, "normalCam = normalMatrix * normal;",
                "normalCam = mat3(modelViewMatrix) * normal;", key);
        break;
    case ShaderMistake::Unnormalized:
        replace(s.fragment, "vec3 N = normalize(normalCam);", "vec3 N = normalCam;", key);
        break;
    case ShaderMistake::LightSpace:
        replace(s.fragment, "vec3 lightCam = (viewMatrix * vec4(lightPosition[i], 1.0)).xyz;",
                "vec3 lightCam = lightPosition[i];", key);
        break;
    case ShaderMistake::HomogeneousW:
        // The lit position only: gl_Position keeps w = 1, or nothing would be drawn.
        replace(s.vertex, "positionCam = p.xyz;",
                "positionCam = (modelViewMatrix * vec4(position, 0.0)).xyz;", key);
        break;
    case ShaderMistake::ReflectIncident:
        replace(s.fragment, "reflect(-L, N)", "reflect(L, N)", key);
        break;
    case ShaderMistake::ViewVector:
        replace(s.fragment, "vec3 V = normalize(-positionCam);", "vec3 V = normalize(positionCam);",
                key);
        break;
    case ShaderMistake::Attenuation:
        replace(s.fragment, "float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);",
                "float fatt = 1.0;", key);
        break;
    case ShaderMistake::NegativeLight:
        // No max(0, N·L) on the diffuse term; the highlight keeps its guard.
        replace(s.fragment, kGuard,
                "        vec3 c0 = attenuation[i];\n"
                "        float f0 = min(1.0 / (c0.x + c0.y * d + c0.z * d * d), 1.0);\n"
                "        if (NdotL <= 0.0) {\n"
                "            I += f0 * Id[i] * kd * NdotL;\n"
                "            continue;\n"
                "        }\n",
                key);
        break;
    case ShaderMistake::BackfaceSpecular:
        // Diffuse clamped, the highlight not guarded by N·L > 0.
        replace(s.fragment, kGuard, "", key);
        replace(s.fragment, "Id[i] * kd * NdotL", "Id[i] * kd * max(0.0, NdotL)", key);
        break;
    case ShaderMistake::Ambient:
        replace(s.fragment, "vec3 I = Ia * ka;", "vec3 I = vec3(0.0);", key);
        break;
    case ShaderMistake::HalfwayVector: replace(s.fragment, kReflected, kHalfway, key); break;
    case ShaderMistake::Gouraud:
    case ShaderMistake::PerFace: qFatal("%s replaces the whole pair", qPrintable(key));
    }
}

} // namespace

ShaderPair withMistake(MistakeVariant variant)
{
    if (variant == MistakeVariant{ShaderMistake::PerFace, MistakeForm::FaceNormalPerFragment})
        return {readShipped(QStringLiteral("faceted.vert")),
                readShipped(QStringLiteral("faceted.frag"))};
    if (variant.form == 0)
        return withMistake(variant.key);
    ShaderPair s = shippedPhong();
    makeForm(s, variant, mistakeVariantName(variant).replace(QLatin1Char('/'), QLatin1Char('-')));
    return s;
}

ShaderPair withMistake(MistakeVariant variant, PhongEquation equation)
{
    if (equation != PhongEquation::Slide)
        return withMistake(variant);
    // The slide's form first (no guard, the diffuse term clamped), then the
    // mistake made in it, as a student who writes that form makes it.
    ShaderPair s = shippedPhong();
    const QString name = QStringLiteral("slide-")
        + mistakeVariantName(variant).replace(QLatin1Char('/'), QLatin1Char('-'));
    replace(s.fragment, kGuard, "", name);
    replace(s.fragment, "Id[i] * kd * NdotL", "Id[i] * kd * max(0.0, NdotL)", name);
    if (variant.form == 0)
        makeKey(s, variant.key);
    else
        makeForm(s, variant, name);
    s.vertex.name = name + QStringLiteral(".vert");
    s.fragment.name = name + QStringLiteral(".frag");
    return s;
}

ShaderPair shippedPhong()
{
    return {readShipped(QStringLiteral("phong.vert")), readShipped(QStringLiteral("phong.frag"))};
}

ShaderPair withMistake(ShaderMistake mistake)
{
    if (mistake == ShaderMistake::Gouraud)
        return {readShipped(QStringLiteral("gouraud.vert")),
                readShipped(QStringLiteral("gouraud.frag"))};
    if (mistake == ShaderMistake::PerFace) // the flat shader, once per face
        return {readShipped(QStringLiteral("flat.vert")), readShipped(QStringLiteral("flat.frag"))};
    ShaderPair s = shippedPhong();
    makeKey(s, mistake);
    return s;
}

ShaderPair withMistakes(const std::vector<MistakeVariant> &set)
{
    ShaderPair s = shippedPhong();
    QStringList names;
    for (MistakeVariant v : set) {
        const QString name = mistakeVariantName(v).replace(QLatin1Char('/'), QLatin1Char('-'));
        if (v.form == 0)
            makeKey(s, v.key);
        else
            makeForm(s, v, name);
        names << name;
    }
    s.vertex.name = names.join(QLatin1Char('+')) + QStringLiteral(".vert");
    s.fragment.name = names.join(QLatin1Char('+')) + QStringLiteral(".frag");
    return s;
}

RgbImage drawPair(OffscreenRenderer &offscreen, const ShaderPair &pair, QSize size)
{
    const BuildReport built = offscreen.renderer().setProgramSources(pair.vertex, pair.fragment);
    if (!built.ok)
        qFatal("%s: %s", qPrintable(pair.fragment.name), qPrintable(built.errorSummary()));
    return toRgbImage(offscreen.renderImage(size));
}

} // namespace phonglab::test
