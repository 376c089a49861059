#pragma once
#include <glm/glm.hpp>

namespace phonglab {

// A pinhole camera looking from eye to target. fovDeg is the vertical field of
// view; the aspect ratio (width / height) comes from the image being rendered.
struct Camera {
    glm::dvec3 eye{0.0, 0.0, 4.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovDeg = 45.0;
    double nearPlane = 0.1;
    double farPlane = 100.0;
    // A view too narrow to show every object moves the eye back until it
    // does (framedCamera), while the user has not moved the camera. False:
    // the camera is a composed shot, shown exactly as saved.
    bool frameObjects = true;

    glm::dmat4 viewMatrix() const;
    glm::dmat4 projectionMatrix(double aspect) const;
    // The same projection clipping at other planes (a fitted DepthRange).
    glm::dmat4 projectionMatrix(double aspect, double nearZ, double farZ) const;
    bool operator==(const Camera &) const = default;
};

} // namespace phonglab
