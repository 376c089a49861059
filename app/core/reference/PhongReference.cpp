#include "core/reference/PhongReference.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace phonglab {

double attenuationFactor(const glm::dvec3 &c, double d)
{
    return std::min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);
}

namespace {

// f_att as the shader computes it: exact, left out, unclamped, or hard-coded.
double attenuationMade(const auto &made, const glm::dvec3 &c, double d)
{
    if (made(ShaderMistake::Attenuation, 0))
        return 1.0;
    if (made(ShaderMistake::Attenuation, MistakeForm::Unclamped))
        return 1.0 / (c.x + c.y * d + c.z * d * d);
    if (made(ShaderMistake::Attenuation, MistakeForm::InverseSquare))
        return 1.0 / (d * d);
    if (made(ShaderMistake::Attenuation, MistakeForm::LearnOpenGl))
        return 1.0 / (1.0 + 0.09 * d + 0.032 * d * d);
    return attenuationFactor(c, d);
}

// The specular model is the only difference between Phong and Blinn-Phong;
// the rest of the equation is shared so the two cannot drift apart.
enum class Specular {
    ReflectedRay,
    HalfVector
};

// Whether the shader makes mistake `m` in form `form`.
struct MadeMistakes {
    std::span<const MistakeVariant> mistakes;
    PhongEquation equation = PhongEquation::Guarded;

    bool operator()(ShaderMistake m, int form = 0) const
    {
        // The slide's equation is the guarded one with backface-specular made.
        if (m == ShaderMistake::BackfaceSpecular && form == 0 && equation == PhongEquation::Slide)
            return true;
        return std::find(mistakes.begin(), mistakes.end(), MistakeVariant{m, form})
            != mistakes.end();
    }
};

// The surface point as every light's term sees it.
struct ShadedPoint {
    glm::dvec3 position{0.0};
    glm::dvec3 N{0.0};
    glm::dvec3 V{0.0};
    Specular model = Specular::ReflectedRay;
    double exponent = 0.0;
};

ShadedPoint shadedPoint(const glm::dvec3 &position, const glm::dvec3 &normal,
                        const Material &material, Specular model, const MadeMistakes &made)
{
    if (made(ShaderMistake::HalfwayVector)
        || made(ShaderMistake::HalfwayVector, MistakeForm::BlinnExponent))
        model = Specular::HalfVector;
    const double exponent = model == Specular::HalfVector && !made(ShaderMistake::HalfwayVector)
        ? kBlinnExponentFactor * material.shininess
        : material.shininess;
    const glm::dvec3 N = made(ShaderMistake::Unnormalized) ? normal : glm::normalize(normal);
    // The eye is at the origin: V = normalize(-P).
    const glm::dvec3 V = glm::normalize(made(ShaderMistake::ViewVector) ? position : -position);
    return ShadedPoint{position, N, V, model, exponent};
}

// max(0, R·V)^n, or max(0, N·H)^n' for the half vector.
double specularFactor(const ShadedPoint &p, const glm::dvec3 &L, const MadeMistakes &made)
{
    if (p.model == Specular::ReflectedRay) {
        const glm::dvec3 R =
            made(ShaderMistake::ReflectIncident) ? glm::reflect(L, p.N) : glm::reflect(-L, p.N);
        return std::pow(std::max(0.0, glm::dot(R, p.V)), p.exponent);
    }
    // L + V vanishes only for a light exactly behind the point as
    // seen from the eye; there is no half vector then, and no highlight.
    const glm::dvec3 sum = L + p.V;
    const double length = glm::length(sum);
    if (length > 0.0) {
        const double NdotH = std::max(0.0, glm::dot(p.N, sum / length));
        return std::pow(NdotH, p.exponent);
    }
    return 0.0;
}

// One light's share of the sum: f_att and, unless the light is behind the
// surface (`lit` false), Id·kd·max(0, N·L) and Is·ks·max(0, R·V)^n.
struct LightTerm {
    double attenuation = 1.0;
    bool lit = false;
    glm::dvec3 diffuse{0.0};
    glm::dvec3 specular{0.0};
};

LightTerm lightTerm(const ShadedPoint &p, const CameraSpaceLight &light, const Material &material,
                    const MadeMistakes &made)
{
    const glm::dvec3 toLight = light.position - p.position;
    const double d = glm::length(toLight);
    const glm::dvec3 L =
        made(ShaderMistake::Unnormalized, MistakeForm::LightUnnormalized) ? toLight : toLight / d;
    const double NdotL = glm::dot(p.N, L);
    LightTerm term;
    term.attenuation = attenuationMade(made, light.attenuation, d);
    // A light behind the surface gives no diffuse and no specular light.
    const bool behind = NdotL <= 0.0;
    if (behind && !made(ShaderMistake::NegativeLight) && !made(ShaderMistake::BackfaceSpecular))
        return term;
    // With max(0, N·L) missing behind the surface the diffuse term goes
    // negative, and there is still no highlight.
    const bool highlight = !behind || made(ShaderMistake::BackfaceSpecular);
    const double specular = highlight ? specularFactor(p, L, made) : 0.0;
    const double diffuseFactor = behind && !made(ShaderMistake::NegativeLight) ? 0.0 : NdotL;
    term.lit = true;
    term.diffuse = light.diffuse * material.kd * diffuseFactor;
    term.specular = light.specular * material.ks * specular;
    return term;
}

// The equation, exact, or with pointwise mistakes (ShaderMistake.h) made
// where a shader would make them: one sequence, so the mistaken images differ
// from the exact one by those mistakes alone, and several combine as they
// do in real code.
IlluminationTerms illumination(const glm::dvec3 &position, const glm::dvec3 &normal,
                               const Material &material, const glm::dvec3 &ambient,
                               std::span<const CameraSpaceLight> lights, Specular model,
                               std::span<const MistakeVariant> mistakes = {},
                               PhongEquation equation = PhongEquation::Guarded)
{
    const MadeMistakes made{mistakes, equation};
    const ShadedPoint point = shadedPoint(position, normal, material, model, made);

    const bool ambientPerLight = made(ShaderMistake::Ambient, MistakeForm::AmbientPerLight);
    const bool ambientAttenuated = made(ShaderMistake::Ambient, MistakeForm::AmbientAttenuated);
    glm::dvec3 I = made(ShaderMistake::Ambient) || ambientPerLight || ambientAttenuated
        ? glm::dvec3(0.0)
        : ambient * material.ka;
    glm::dvec3 S(0.0); // the specular part alone, summed beside I (I itself is unchanged)
    for (const CameraSpaceLight &light : lights) {
        const LightTerm term = lightTerm(point, light, material, made);
        if (ambientPerLight)
            I += ambient * material.ka;
        if (ambientAttenuated)
            I += term.attenuation * ambient * material.ka;
        if (!term.lit)
            continue;
        I += term.attenuation * (term.diffuse + term.specular);
        S += term.attenuation * term.specular;
    }
    return {I, S};
}

} // namespace

glm::dvec3 phongIntensity(const glm::dvec3 &position, const glm::dvec3 &normal,
                          const Material &material, const glm::dvec3 &ambient,
                          std::span<const CameraSpaceLight> lights)
{
    return illumination(position, normal, material, ambient, lights, Specular::ReflectedRay)
        .intensity;
}

glm::dvec3 blinnPhongIntensity(const glm::dvec3 &position, const glm::dvec3 &normal,
                               const Material &material, const glm::dvec3 &ambient,
                               std::span<const CameraSpaceLight> lights)
{
    return illumination(position, normal, material, ambient, lights, Specular::HalfVector)
        .intensity;
}

IlluminationTerms phongTerms(const glm::dvec3 &position, const glm::dvec3 &normal,
                             const Material &material, const glm::dvec3 &ambient,
                             std::span<const CameraSpaceLight> lights)
{
    return illumination(position, normal, material, ambient, lights, Specular::ReflectedRay);
}

IlluminationTerms blinnPhongTerms(const glm::dvec3 &position, const glm::dvec3 &normal,
                                  const Material &material, const glm::dvec3 &ambient,
                                  std::span<const CameraSpaceLight> lights)
{
    return illumination(position, normal, material, ambient, lights, Specular::HalfVector);
}

IlluminationTerms mistakenPhongTerms(const glm::dvec3 &position, const glm::dvec3 &normal,
                                     const Material &material, const glm::dvec3 &ambient,
                                     std::span<const CameraSpaceLight> lights,
                                     std::span<const MistakeVariant> mistakes,
                                     PhongEquation equation)
{
    return illumination(position, normal, material, ambient, lights, Specular::ReflectedRay,
                        mistakes, equation);
}

glm::dvec3 normalViewColor(const glm::dvec3 &normal)
{
    return 0.5 * glm::normalize(normal) + 0.5;
}

CameraSpaceLight toCameraSpace(const PointLight &light, const glm::dmat4 &view)
{
    CameraSpaceLight out;
    out.position = glm::dvec3(view * glm::dvec4(light.position, 1.0)); // a point: w = 1
    out.diffuse = light.diffuse;
    out.specular = light.specular;
    out.attenuation = light.attenuation;
    return out;
}

int encodeChannel(double intensity)
{
    return static_cast<int>(std::lround(std::clamp(intensity, 0.0, 1.0) * 255.0));
}

} // namespace phonglab
