#pragma once
#include "PolygonMesh.h"

namespace phonglab {

// True when every edge is shared by exactly two faces: the surface encloses
// a volume, so back faces are never visible and may be culled.
bool isClosedSurface(const PolygonMesh &mesh);

} // namespace phonglab
