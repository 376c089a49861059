#include "ReferenceSample.h"

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

ReferenceSample shadeReferenceHit(const ObjectSpaceHit &hit, const Material &material,
                                  const glm::dvec3 &ambient,
                                  std::span<const CameraSpaceLight> lights,
                                  const ReferenceShader &shader)
{
    const double w = shader.makes(ShaderMistake::HomogeneousW) ? 0.0 : 1.0;
    const glm::dvec3 position = glm::dvec3(hit.modelView * glm::dvec4(hit.point, w));
    const glm::dvec3 normal = shader.makes(ShaderMistake::NormalMatrix)
        ? glm::dmat3(hit.modelView) * hit.normal
        : hit.normalMatrix * hit.normal;
    if (shader.shading == ReferenceShading::Phong && shader.mistake
        && isPointwiseMistake(*shader.mistake)) {
        const IlluminationTerms terms =
            mistakenPhongTerms(position, normal, material, ambient, lights, *shader.mistake);
        return {terms.intensity, terms.specular};
    }
    return shadeReferenceSample(position, normal, material, ambient, lights, shader.shading);
}

std::vector<CameraSpaceLight> enabledCameraSpaceLights(const Scene &scene,
                                                       const ReferenceShader &shader)
{
    const glm::dmat4 view =
        shader.makes(ShaderMistake::LightSpace) ? glm::dmat4(1.0) : scene.camera.viewMatrix();
    std::vector<CameraSpaceLight> lights;
    lights.reserve(scene.lights.size());
    for (const PointLight &light : scene.lights)
        if (light.enabled)
            lights.push_back(toCameraSpace(light, view));
    return lights;
}

} // namespace phonglab
