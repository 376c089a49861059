#include "core/reference/ReferenceSample.h"

#include <algorithm>

namespace phonglab {

ReferenceSample shadeReferenceSample(const glm::dvec3 &position, const glm::dvec3 &normal,
                                     const Material &material, const glm::dvec3 &ambient,
                                     std::span<const CameraSpaceLight> lights,
                                     ReferenceShading shading)
{
    IlluminationTerms terms;
    switch (shading) {
    case ReferenceShading::Phong:
        terms = phongTerms(position, normal, material, ambient, lights);
        break;
    case ReferenceShading::BlinnPhong:
        terms = blinnPhongTerms(position, normal, material, ambient, lights);
        break;
    case ReferenceShading::Normals: return {normalViewColor(normal), glm::dvec3(0.0)};
    }
    return {terms.intensity, terms.specular};
}

namespace {

// N as the vertex shader moves it, rightly or in one of the mistakes' forms.
glm::dvec3 movedNormal(const ObjectSpaceHit &hit, const ReferenceShader &shader)
{
    const glm::dmat3 modelView(hit.modelView);
    // One transform of N: where a set of mistakes names two, the first
    // below wins (MistakeSets never combines them).
    if (shader.makes(ShaderMistake::NormalMatrix))
        return modelView * hit.normal;
    if (shader.makes(ShaderMistake::NormalMatrix, MistakeForm::NormalByModel))
        return glm::dmat3(hit.model) * hit.normal;
    if (shader.makes(ShaderMistake::NormalMatrix, MistakeForm::NormalByTranspose))
        return glm::transpose(modelView) * hit.normal;
    if (shader.makes(ShaderMistake::HomogeneousW, MistakeForm::NormalWithW1))
        return glm::dvec3(hit.modelView * glm::dvec4(hit.normal, 1.0));
    return hit.normalMatrix * hit.normal;
}

} // namespace

ReferenceSample shadeReferenceHit(const ObjectSpaceHit &hit, const Material &material,
                                  const glm::dvec3 &ambient,
                                  std::span<const CameraSpaceLight> lights,
                                  const ReferenceShader &shader)
{
    const double w = shader.makes(ShaderMistake::HomogeneousW) ? 0.0 : 1.0;
    const glm::dvec3 position = glm::dvec3(hit.modelView * glm::dvec4(hit.point, w));
    const glm::dvec3 normal = movedNormal(hit, shader);
    // Lights moved by the model-view matrix: enabledCameraSpaceLights() left
    // them in world coordinates, and each object moves them by its own.
    std::vector<CameraSpaceLight> moved;
    if (shader.makes(ShaderMistake::LightSpace, MistakeForm::LightByModelView)) {
        moved.assign(lights.begin(), lights.end());
        for (CameraSpaceLight &light : moved)
            light.position = glm::dvec3(hit.modelView * glm::dvec4(light.position, 1.0));
        lights = moved;
    }
    const bool pointwise = std::any_of(shader.mistakes.begin(), shader.mistakes.end(),
                                       [](MistakeVariant v) { return isPointwiseMistake(v.key); });
    if (shader.shading == ReferenceShading::Phong
        && (pointwise || shader.equation == PhongEquation::Slide)) {
        const IlluminationTerms terms = mistakenPhongTerms(
            position, normal, material, ambient, lights, shader.mistakes, shader.equation);
        return {terms.intensity, terms.specular};
    }
    return shadeReferenceSample(position, normal, material, ambient, lights, shader.shading);
}

std::vector<CameraSpaceLight> enabledCameraSpaceLights(const Scene &scene,
                                                       const ReferenceShader &shader)
{
    const bool inWorld = shader.makes(ShaderMistake::LightSpace)
        || shader.makes(ShaderMistake::LightSpace, MistakeForm::LightByModelView);
    const glm::dmat4 view = inWorld ? glm::dmat4(1.0) : scene.camera.viewMatrix();
    const bool asDirection = shader.makes(ShaderMistake::HomogeneousW, MistakeForm::LightWithW0);
    std::vector<CameraSpaceLight> lights;
    lights.reserve(scene.lights.size());
    for (const PointLight &light : scene.lights) {
        if (!light.enabled)
            continue;
        CameraSpaceLight moved = toCameraSpace(light, view);
        if (asDirection)
            moved.position = glm::dvec3(view * glm::dvec4(light.position, 0.0));
        lights.push_back(moved);
    }
    return lights;
}

} // namespace phonglab
