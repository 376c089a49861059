#pragma once
#include "Camera.h"

#include <glm/vec3.hpp>

namespace phonglab {

// Where a new light is seen at once: between the eye and the target, up
// and to one side, well inside the view (a light outside it cannot be
// picked, and the student does not know it was added). The `index`-th new
// light takes the other side from the one before.
glm::dvec3 visibleLightPosition(const Camera &camera, int index);

// Whether `point` is in the view of `camera` at `aspect`, `margin` of the
// half-width in from its edges (0: anywhere in it), and in front of the eye.
bool isInView(const Camera &camera, double aspect, const glm::dvec3 &point, double margin = 0.0);

} // namespace phonglab
