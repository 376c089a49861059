#pragma once
#include "PolygonMesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace phonglab {

// Polygons split into triangles. Each triangle is three corner indices into
// the PolygonMesh's corner arrays (cornerPosition / cornerNormal), not
// position indices, so every triangle corner keeps the normal the file gave
// that polygon corner.
struct Triangulation {
    std::vector<std::uint32_t> corners; // 3 per triangle
    std::size_t fanFallbacks = 0;       // polygons ear clipping could not handle

    std::size_t triangleCount() const { return corners.size() / 3; }
};

// Triangles pass through; quads split along whichever diagonal keeps both
// halves facing the quad's way; other convex polygons become a fan; the
// rest are ear-clipped in the plane of their Newell normal, and where that
// fails (self-intersecting or degenerate outlines) the remainder is
// fanned. Triangles wind like the polygon: their normals agree with its
// Newell normal.
Triangulation triangulate(const PolygonMesh &mesh);

// The polygon's Newell normal (not normalised): the area-weighted normal of
// its best-fit plane, robust for non-planar and concave polygons.
glm::dvec3 newellNormal(std::span<const glm::vec3> positions,
                        std::span<const std::uint32_t> polygon);

} // namespace phonglab
