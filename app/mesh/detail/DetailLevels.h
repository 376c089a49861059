#pragma once
#include "core/scene/MeshData.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace phonglab {

// The levels of detail behind "detail": "auto": the same vertices, ever
// fewer triangles, each level with the geometric error the simplifier
// reports for it (meshoptimizer's meshopt_simplify, chosen over OpenMesh's
// Decimater by measurement: 11-25x faster at a mean deviation within 10 %,
// and it states its error; docs/speed-vs-accuracy.md).
//
// Every level indexes the full mesh's vertex array, so on the GPU the levels
// share one vertex buffer and differ in their index ranges only; vertex
// normals stay as the file gave them (attribute seams are kept as seams).
struct DetailLevel {
    std::vector<std::uint32_t> indices;
    double error = 0.0; // object units: how far this level's surface may stray
    // Radians: how far the normal a pixel is shaded with may be off: the
    // largest angle between the normal the full mesh and this level are
    // shaded with where the same view ray meets them, over rays towards up
    // to kNormalSamples points of the full mesh (its vertices and triangle
    // centres) along the normal and kGrazingDeg off it four ways. Never
    // less than the level before's. A wrong normal changes the shading
    // however small the object is on screen.
    double normalDeviation = 0.0;
};

struct DetailLevels {
    // levels[0] is the full mesh (error 0); each next level has about half
    // the triangles of the one before and an error no smaller.
    std::vector<DetailLevel> levels;

    bool empty() const { return levels.empty(); }
    std::size_t triangles(std::size_t level) const { return levels[level].indices.size() / 3; }
};

// Halves the triangle count level by level until fewer than
// kMinLevelTriangles remain or the simplifier cannot reduce by a tenth any
// more. Each level is simplified from the one before, so its error is the
// sum of the steps' errors (a bound: each step's error is measured against
// its input). `progress(fraction)` may return false to cancel: the result is
// then empty. `mesh` must be valid.
inline constexpr std::size_t kMinLevelTriangles = 64;
inline constexpr std::size_t kNormalSamples = 20000;
inline constexpr double kGrazingDeg = 70.0;
DetailLevels buildDetailLevels(const MeshData &mesh,
                               const std::function<bool(double)> &progress = {});

} // namespace phonglab
