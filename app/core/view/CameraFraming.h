#pragma once
#include "Camera.h"

#include <glm/glm.hpp>
#include <span>

namespace phonglab {

// The camera moved back along its line of sight, never closer than it was,
// until every point lies inside the view of `aspect` (width / height), with
// `margin` of each half-field to spare. A scene's camera is chosen for one
// shape of view; a narrower view would cut off what it was meant to show.
// Only the eye moves: target, up, field of view and planes stay, so a view
// that already shows everything keeps the scene's camera exactly.
Camera framedCamera(const Camera &camera, std::span<const glm::dvec3> points, double aspect,
                    double margin = 0.05);

} // namespace phonglab
