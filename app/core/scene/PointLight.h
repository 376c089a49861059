#pragma once
#include <glm/glm.hpp>
#include <string>

namespace phonglab {

// A point light placed in world coordinates. diffuse is Id, specular is Is,
// attenuation holds (c1, c2, c3) of f_att = min(1 / (c1 + c2·d + c3·d²), 1).
struct PointLight {
    glm::dvec3 position{0.0, 0.0, 0.0};
    glm::dvec3 diffuse{1.0, 1.0, 1.0};
    glm::dvec3 specular{1.0, 1.0, 1.0};
    glm::dvec3 attenuation{1.0, 0.0, 0.0};
    // Shown in the Lights dock; empty means "Light N" (N = index + 1). UTF-8.
    std::string name;
    // A disabled light stays in the scene (and the file) but lights nothing:
    // it is not sent to the shader nor used by the CPU reference.
    bool enabled = true;

    bool operator==(const PointLight &) const = default;
};

inline constexpr int kMaxLights = 8;

} // namespace phonglab
