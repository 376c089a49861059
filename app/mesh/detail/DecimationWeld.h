#pragma once
// Internal to MeshDecimation.cpp and DecimationWeld.cpp: MeshData welded by
// exact position for OpenMesh, and the decimated faces taken back into
// MeshData with the input's own normals. Apart from the decimation itself
// (MeshDecimation.cpp), which runs between the two.
#include "core/scene/MeshData.h"

#include "DecimationMesh.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace phonglab::decimation {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// The input welded by exact position: OpenMesh needs one vertex per point
// to see the surface's connectivity, while MeshData splits a point into one
// GPU vertex per normal. The split normals are kept aside as candidates.
struct Weld {
    std::vector<std::uint32_t> weldedOf;   // per input GPU vertex (kNone: unused)
    std::vector<std::uint32_t> firstGpu;   // per welded vertex: a GPU vertex there (its position)
    std::vector<std::uint32_t> candStart;  // CSR offsets into candidates, per welded vertex + 1
    std::vector<std::uint32_t> candidates; // GPU vertices with distinct normals, per welded vertex
};

Weld weldByPosition(const MeshData &mesh);

// A faceted mesh's three corners of every triangle carry one normal.
bool isFaceted(const MeshData &mesh);

// The faces of `om` still there, as MeshData: positions the input's, each
// corner with the normal the input had there (MeshDecimation.h says which).
MeshData rebuild(const MeshData &input, const Weld &w, const OmMesh &om,
                 const std::vector<std::uint32_t> &faceTriangle, bool faceted);

} // namespace phonglab::decimation
