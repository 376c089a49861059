#include "OrbitCamera.h"

#include <algorithm>
#include <cmath>

namespace phonglab {

namespace {

constexpr double kTiny = 1e-12;
// Closest approach, in multiples of the near plane: any closer and the
// object at the target is mostly clipped away.
constexpr double kMinDistanceOverNear = 1.5;
// Farthest, as a fraction of the far plane, so the target stays in view.
constexpr double kMaxDistanceOverFar = 0.9;

// Any unit vector perpendicular to `axis` (unit).
glm::dvec3 anyPerpendicular(const glm::dvec3 &axis)
{
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(axis, helper));
}

} // namespace

OrbitCamera::OrbitCamera(const Camera &original)
{
    setOriginal(original);
}

void OrbitCamera::setOriginal(const Camera &original)
{
    m_original = original;
    m_camera = original;
}

void OrbitCamera::reset()
{
    m_camera = m_original;
}

double OrbitCamera::distance() const
{
    return glm::length(m_camera.eye - m_camera.target);
}

glm::dvec3 OrbitCamera::upAxis() const
{
    const double length = glm::length(m_camera.up);
    return length > kTiny ? m_camera.up / length : glm::dvec3(0, 1, 0);
}

void OrbitCamera::orbit(double yawDeg, double pitchDeg)
{
    const glm::dvec3 offset = m_camera.eye - m_camera.target;
    const double radius = glm::length(offset);
    if (radius < kTiny)
        return;

    // Spherical coordinates about the up axis: polar angle from "up", and
    // the unit direction of the offset's horizontal part.
    const glm::dvec3 up = upAxis();
    const double vertical = glm::dot(offset, up);
    const glm::dvec3 horizontal = offset - vertical * up;
    const double horizontalLength = glm::length(horizontal);
    const glm::dvec3 h =
        horizontalLength > kTiny * radius ? horizontal / horizontalLength : anyPerpendicular(up);
    const double polar = std::acos(std::clamp(vertical / radius, -1.0, 1.0));

    // h is perpendicular to up, so rotating it about up is this 2D rotation.
    const double yaw = glm::radians(yawDeg);
    const glm::dvec3 newH = h * std::cos(yaw) + glm::cross(up, h) * std::sin(yaw);
    const double margin = glm::radians(kPoleMarginDeg);
    const double newPolar = std::clamp(polar - glm::radians(pitchDeg), margin, M_PI - margin);

    m_camera.eye = m_camera.target + radius * (std::cos(newPolar) * up + std::sin(newPolar) * newH);
}

void OrbitCamera::pan(double dx, double dy)
{
    const glm::dvec3 offset = m_camera.eye - m_camera.target;
    const double radius = glm::length(offset);
    if (radius < kTiny)
        return;

    const glm::dvec3 forward = -offset / radius;
    glm::dvec3 right = glm::cross(forward, upAxis());
    const double rightLength = glm::length(right);
    right = rightLength > kTiny ? right / rightLength : anyPerpendicular(forward);
    const glm::dvec3 screenUp = glm::cross(right, forward);

    // World units spanned by one view height at the target's distance.
    const double viewHeight = 2.0 * radius * std::tan(glm::radians(m_camera.fovDeg) / 2.0);
    // The scene follows the cursor, so the camera moves the other way.
    const glm::dvec3 shift = viewHeight * (-dx * right + dy * screenUp);
    m_camera.eye += shift;
    m_camera.target += shift;
}

void OrbitCamera::zoom(double factor)
{
    const glm::dvec3 offset = m_camera.eye - m_camera.target;
    const double radius = glm::length(offset);
    if (radius < kTiny || !(factor > 0.0))
        return;

    double newRadius = radius * factor;
    // Clamp only in the direction of travel, so a scene whose camera starts
    // outside the limits does not jump on the first wheel step.
    if (factor < 1.0)
        newRadius =
            std::max(newRadius, std::min(radius, kMinDistanceOverNear * m_camera.nearPlane));
    else
        newRadius = std::min(newRadius, std::max(radius, kMaxDistanceOverFar * m_camera.farPlane));

    m_camera.eye = m_camera.target + offset * (newRadius / radius);
}

} // namespace phonglab
