#pragma once
#include "PageCapture.h"

#include <glm/vec4.hpp>

#include <optional>
#include <vector>

namespace phonglab {

// A captured draw's vertices as the vertex shader received them.

// The vertex indices the draw reads, in order (first..first+count-1, or
// its index buffer's, restarts left out); nullopt when the draw does not
// fit its buffers (core/page/CaptureBounds).
std::optional<std::vector<qint64>> drawnVertices(const PageCapture &capture,
                                                 const CapturedOp &draw);

// The attribute's value at each vertex (missing components 0, w 1, as GL
// fills them; normalised integers mapped as WebGL maps them); the constant
// value for a disabled attribute.
std::vector<glm::dvec4> attributeValues(const PageCapture &capture,
                                        const CapturedAttribute &attribute,
                                        const std::vector<qint64> &vertices);

} // namespace phonglab
