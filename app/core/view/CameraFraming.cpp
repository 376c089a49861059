#include "CameraFraming.h"

#include <algorithm>
#include <cmath>

namespace phonglab {

namespace {

// The distance from target to eye at which `point` sits on or inside both
// pairs of side planes; offsets are in the camera's right, up and forward
// directions about the target.
double distanceToSee(const glm::dvec3 &offset, double tanHalfWidth, double tanHalfHeight)
{
    const double depthBeyondTarget = offset.z;
    return std::max(std::abs(offset.x) / tanHalfWidth, std::abs(offset.y) / tanHalfHeight)
        - depthBeyondTarget;
}

} // namespace

Camera framedCamera(const Camera &camera, std::span<const glm::dvec3> points, double aspect,
                    double margin)
{
    const glm::dvec3 line = camera.target - camera.eye;
    const double distance = glm::length(line);
    if (points.empty() || !(aspect > 0.0) || !(distance > 0.0) || !std::isfinite(distance))
        return camera;
    const glm::dvec3 forward = line / distance;
    const glm::dvec3 side = glm::cross(forward, camera.up);
    if (!(glm::length(side) > 0.0))
        return camera; // looking along up: no defined right
    const glm::dvec3 right = glm::normalize(side);
    const glm::dvec3 up = glm::cross(right, forward);
    const double keep = std::clamp(1.0 - margin, 0.1, 1.0);
    const double tanHalfHeight = std::tan(glm::radians(camera.fovDeg) / 2.0) * keep;
    const double tanHalfWidth = tanHalfHeight * aspect;
    if (!(tanHalfHeight > 0.0) || !std::isfinite(tanHalfHeight))
        return camera;
    double needed = distance;
    for (const glm::dvec3 &point : points) {
        const glm::dvec3 p = point - camera.target;
        const glm::dvec3 offset{glm::dot(p, right), glm::dot(p, up), glm::dot(p, forward)};
        needed = std::max(needed, distanceToSee(offset, tanHalfWidth, tanHalfHeight));
    }
    if (!std::isfinite(needed) || needed <= distance)
        return camera;
    Camera framed = camera;
    framed.eye = camera.target - forward * needed;
    return framed;
}

} // namespace phonglab
