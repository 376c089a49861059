#pragma once
#include <glm/glm.hpp>

namespace phonglab {

// An object's placement in the world. The model matrix is T · Rz · Ry · Rx · S:
// scale first, then rotate about X, Y, Z (degrees), then translate.
struct Transform {
    glm::dvec3 translate{0.0};
    glm::dvec3 rotateDeg{0.0};
    glm::dvec3 scale{1.0};

    glm::dmat4 matrix() const;
    bool operator==(const Transform &) const = default;
};

} // namespace phonglab
