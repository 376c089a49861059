#include "ReferenceSample.h"

namespace phonglab {

ReferenceSample shadeReferenceSample(const glm::dvec3 &position, const glm::dvec3 &normal,
                                     const Material &material, const glm::dvec3 &ambient,
                                     std::span<const CameraSpaceLight> lights, ReferenceShading shading)
{
    IlluminationTerms terms;
    switch (shading) {
    case ReferenceShading::Phong: terms = phongTerms(position, normal, material, ambient, lights); break;
    case ReferenceShading::BlinnPhong: terms = blinnPhongTerms(position, normal, material, ambient, lights); break;
    case ReferenceShading::Normals: return {normalViewColor(normal), glm::dvec3(0.0)};
    }
    return {terms.intensity, terms.specular};
}

std::vector<CameraSpaceLight> enabledCameraSpaceLights(const Scene &scene)
{
    const glm::dmat4 view = scene.camera.viewMatrix();
    std::vector<CameraSpaceLight> lights;
    lights.reserve(scene.lights.size());
    for (const PointLight &light : scene.lights)
        if (light.enabled)
            lights.push_back(toCameraSpace(light, view));
    return lights;
}

} // namespace phonglab
