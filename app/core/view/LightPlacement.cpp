#include "LightPlacement.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

#include <cmath>

namespace phonglab {

namespace {

// How far along the way from the eye to the target, and how far out from
// the view's centre (a fraction of its half-height): off the objects,
// which sit at the target, and clear of the edges.
constexpr double kAlongTheWay = 0.55;
constexpr double kOutFromCentre = 0.5;

} // namespace

glm::dvec3 visibleLightPosition(const Camera &camera, int index)
{
    const glm::dvec3 toTarget = camera.target - camera.eye;
    const double distance = glm::length(toTarget);
    if (distance <= 0.0)
        return camera.eye + glm::dvec3(0.0, 0.0, -1.0);
    const glm::dvec3 forward = toTarget / distance;
    glm::dvec3 right = glm::cross(forward, camera.up);
    if (glm::length(right) < 1e-9)
        right = glm::dvec3(1.0, 0.0, 0.0);
    right = glm::normalize(right);
    const glm::dvec3 up = glm::cross(right, forward);
    const double along = kAlongTheWay * distance;
    const double halfHeight = along * std::tan(glm::radians(camera.fovDeg) / 2.0);
    const double side = index % 2 == 0 ? 1.0 : -1.0;
    return camera.eye + forward * along + right * (side * kOutFromCentre * halfHeight)
        + up * (kOutFromCentre * halfHeight);
}

bool isInView(const Camera &camera, double aspect, const glm::dvec3 &point, double margin)
{
    const glm::dvec4 clip =
        camera.projectionMatrix(aspect) * camera.viewMatrix() * glm::dvec4(point, 1.0);
    if (clip.w <= 0.0)
        return false;
    const double limit = 1.0 - margin;
    return std::abs(clip.x / clip.w) <= limit && std::abs(clip.y / clip.w) <= limit
        && std::abs(clip.z / clip.w) <= 1.0;
}

} // namespace phonglab
