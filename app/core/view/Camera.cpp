#include "Camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace phonglab {

glm::dmat4 Camera::viewMatrix() const
{
    return glm::lookAt(eye, target, up);
}

glm::dmat4 Camera::projectionMatrix(double aspect) const
{
    return projectionMatrix(aspect, nearPlane, farPlane);
}

glm::dmat4 Camera::projectionMatrix(double aspect, double nearZ, double farZ) const
{
    return glm::perspective(glm::radians(fovDeg), aspect, nearZ, farZ);
}

} // namespace phonglab
