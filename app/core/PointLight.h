#pragma once
#include <glm/glm.hpp>

namespace phonglab {

// A point light placed in world coordinates. diffuse is Id, specular is Is,
// attenuation holds (c1, c2, c3) of f_att = min(1 / (c1 + c2·d + c3·d²), 1).
struct PointLight {
    glm::dvec3 position{0.0, 0.0, 0.0};
    glm::dvec3 diffuse{1.0, 1.0, 1.0};
    glm::dvec3 specular{1.0, 1.0, 1.0};
    glm::dvec3 attenuation{1.0, 0.0, 0.0};

    bool operator==(const PointLight &) const = default;
};

inline constexpr int kMaxLights = 8;

} // namespace phonglab
