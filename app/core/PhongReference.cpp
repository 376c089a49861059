#include "PhongReference.h"

#include <algorithm>
#include <cmath>

namespace phonglab {

double attenuationFactor(const glm::dvec3 &c, double d)
{
    return std::min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);
}

glm::dvec3 phongIntensity(const glm::dvec3 &position, const glm::dvec3 &normal,
                          const Material &material, const glm::dvec3 &ambient,
                          std::span<const CameraSpaceLight> lights)
{
    const glm::dvec3 N = glm::normalize(normal);
    const glm::dvec3 V = glm::normalize(-position); // the eye is at the origin

    glm::dvec3 I = ambient * material.ka;
    for (const CameraSpaceLight &light : lights) {
        const glm::dvec3 toLight = light.position - position;
        const double d = glm::length(toLight);
        const glm::dvec3 L = toLight / d;
        const double NdotL = glm::dot(N, L);
        if (NdotL <= 0.0)
            continue; // light behind the surface: no diffuse, no specular
        const glm::dvec3 R = glm::reflect(-L, N);
        const double RdotV = std::max(0.0, glm::dot(R, V));
        const glm::dvec3 diffuse = light.diffuse * material.kd * NdotL;
        const glm::dvec3 specular = light.specular * material.ks * std::pow(RdotV, material.shininess);
        I += attenuationFactor(light.attenuation, d) * (diffuse + specular);
    }
    return I;
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
