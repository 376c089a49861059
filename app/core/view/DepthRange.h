#pragma once
#include "Camera.h"

#include <QString>
#include <glm/glm.hpp>
#include <optional>
#include <span>

namespace phonglab {

// A sphere in world space that holds everything one draw call can put on
// screen (an object's mesh bounds under its model matrix, a light marker).
struct BoundingSphere {
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

// The sphere around an axis-aligned box [lo, hi] after `model`.
BoundingSphere boundingSphere(const glm::dvec3 &lo, const glm::dvec3 &hi, const glm::dmat4 &model);

// The near and far planes a frame is drawn with. A camera may ask for
// near 1e-9 and far 1e12; a 24-bit depth buffer spread over that range
// cannot tell any two surfaces apart and the frame comes out empty or
// scrambled. Clipping at a plane that no geometry lies beyond changes no
// pixel, so the planes move inwards to the depth interval the spheres
// occupy (with a little slack), never outwards: the image is the one the
// camera asked for, drawn with the depth precision the scene needs.
struct DepthRange {
    double nearPlane = 0.1;
    double farPlane = 100.0;

    // far / near; the depth buffer's resolution at distance z is about
    // z · (far/near) / 2^24 of z.
    double ratio() const { return farPlane / nearPlane; }
};

DepthRange fitDepthRange(const Camera &camera, std::span<const BoundingSphere> spheres);

// Above this far/near even the fitted range leaves surfaces within a few
// percent of their distance indistinguishable (the eye inside an object's
// bounds with a tiny near plane): worth a word to the user.
inline constexpr double kDepthRatioWarning = 1e6;

// "camera: near 1e-09 ... " when `range` is past kDepthRatioWarning, else nothing.
std::optional<QString> depthPrecisionWarning(const DepthRange &range);

} // namespace phonglab
