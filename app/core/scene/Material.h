#pragma once
#include <glm/glm.hpp>

namespace phonglab {

// Phong material: per-channel reflection coefficients and the specular exponent n.
struct Material {
    glm::dvec3 ka{0.2, 0.2, 0.2};
    glm::dvec3 kd{0.6, 0.6, 0.6};
    glm::dvec3 ks{0.5, 0.5, 0.5};
    double shininess = 32.0;

    bool operator==(const Material &) const = default;
};

} // namespace phonglab
