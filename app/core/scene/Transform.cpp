#include "Transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace phonglab {

glm::dmat4 Transform::matrix() const
{
    const glm::dmat4 identity(1.0);
    const glm::dmat4 t = glm::translate(identity, translate);
    const glm::dmat4 rx = glm::rotate(identity, glm::radians(rotateDeg.x), glm::dvec3(1, 0, 0));
    const glm::dmat4 ry = glm::rotate(identity, glm::radians(rotateDeg.y), glm::dvec3(0, 1, 0));
    const glm::dmat4 rz = glm::rotate(identity, glm::radians(rotateDeg.z), glm::dvec3(0, 0, 1));
    const glm::dmat4 s = glm::scale(identity, scale);
    return t * rz * ry * rx * s;
}

} // namespace phonglab
