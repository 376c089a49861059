#pragma once
#include "core/scene/NormalOptions.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace phonglab {

// Unit normals for every corner of a triangle mesh, stored indexed: corner c
// (corner c % 3 of triangle c / 3) has normals[index(c)]. How the index is
// found depends on the method, which spares writing out an index per
// corner when it would only repeat what is known:
//   PerPosition  smooth normals without a crease, one per position: the
//                triangles' position indices double as normal indices;
//   PerTriangle  flat normals, one per triangle: the index is c / 3;
//   PerCorner    everything else: cornerNormal holds one index per corner.
struct CornerNormals {
    enum class Indexing {
        PerPosition,
        PerTriangle,
        PerCorner
    };

    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> cornerNormal; // PerCorner only
    Indexing indexing = Indexing::PerCorner;

    std::uint32_t index(std::size_t corner, std::span<const std::uint32_t> triangles) const
    {
        switch (indexing) {
        case Indexing::PerPosition: return triangles[corner];
        case Indexing::PerTriangle: return std::uint32_t(corner / 3);
        case Indexing::PerCorner: break;
        }
        return cornerNormal[corner];
    }
    const glm::vec3 &at(std::size_t corner, std::span<const std::uint32_t> triangles) const
    {
        return normals[index(corner, triangles)];
    }
};

// Computes normals for triangles (three position indices each) by `method`
// (Auto means AngleWeighted):
//   Flat          the triangle's own normal at each of its corners;
//   Average       the unweighted mean of the unit normals of the triangles at the vertex;
//   AreaWeighted  their sum weighted by triangle area;
//   AngleWeighted weighted by the triangle's interior angle at the vertex.
// With a crease angle, a corner averages only the triangles it reaches
// around its vertex across edges whose two triangles' normals differ by at
// most that angle: sharp edges split the vertex into smoothing groups.
// A corner whose sum cancels to nothing (faces back to back) gets its
// triangle's normal. Degenerate triangles add nothing; a corner with
// nothing else to go on (it sees only degenerate, hence invisible,
// triangles) gets +Z. Every normal is finite and unit length.
// Triangles × 3 must fit in 32 bits (MeshBuilder checks).
CornerNormals computeNormals(std::span<const glm::vec3> positions,
                             std::span<const std::uint32_t> triangles, NormalMethod method,
                             std::optional<double> creaseAngleDeg = std::nullopt);

// One normal per triangle corner, written out (3 per triangle); for tests
// and callers that want the plain array.
std::vector<glm::vec3> expandCornerNormals(const CornerNormals &normals,
                                           std::span<const std::uint32_t> triangles);

} // namespace phonglab
