#include "NormalComputation.h"

#include "CreasedNormals.h"
#include "NormalMath.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <utility>

namespace phonglab {

namespace {

using namespace normals;

CornerNormals flatNormals(std::span<const glm::vec3> positions,
                          std::span<const std::uint32_t> triangles)
{
    CornerNormals result;
    result.indexing = CornerNormals::Indexing::PerTriangle;
    const std::size_t count = triangles.size() / 3;
    result.normals.resize(count);
    for (std::size_t t = 0; t < count; ++t) {
        const glm::vec3 &a = positions[triangles[3 * t]];
        const glm::vec3 n = normalizedOrZero(
            glm::cross(positions[triangles[3 * t + 1]] - a, positions[triangles[3 * t + 2]] - a));
        // A degenerate triangle is invisible; any normal will do.
        result.normals[t] = isZero(n) ? kLastResort : n;
    }
    return result;
}

// The hot path: one pass scattering weighted triangle normals onto their
// vertices, then one normalising each vertex's sum. The method is a
// template argument so each variant compiles to its own tight loop.
template <NormalMethod Method>
void accumulate(const glm::vec3 *positions, const std::uint32_t *triangles, std::size_t count,
                Accumulator *sums)
{
    for (std::size_t t = 0; t < count; ++t, triangles += 3) {
        const std::uint32_t i0 = triangles[0], i1 = triangles[1], i2 = triangles[2];
        const glm::vec3 a = positions[i0];
        const glm::vec3 n = glm::cross(positions[i1] - a, positions[i2] - a);
        Accumulator add;
        if constexpr (Method == NormalMethod::Average) {
            // Unit length (selects, not branches: degenerate triangles come
            // unpredictably, and add nothing).
            const float length = std::sqrt(glm::dot(n, n));
            const float valid = length > 0.0f ? 1.0f : 0.0f;
            add = Accumulator(n * (valid / std::max(length, kTiny)), valid);
        } else {
            // |n| is twice the area: the raw cross product is the weighted
            // normal.
            add = Accumulator(n, sizeOf(n));
        }
        sums[i0] += add;
        sums[i1] += add;
        sums[i2] += add;
    }
}

// Angle weighting needs two angles per triangle (the third is π minus
// those). Computed inline, their arithmetic was several times the rest of
// the loop. So triangles go in blocks: gather a block's cross and dot
// products, turn them into weights in a loop without indirection (which
// the compiler vectorises), then scatter.
void accumulateAngleWeighted(const glm::vec3 *positions, const std::uint32_t *triangles,
                             std::size_t count, Accumulator *sums)
{
    constexpr std::size_t kBlock = 256;
    glm::vec3 normal[kBlock];
    // Zeroed once: a short last block leaves stale but finite values behind.
    alignas(16) float doubleArea[kBlock] = {}, dotA[kBlock] = {}, dotB[kBlock] = {};
    // Per corner: the angle, and the factor that turns the cross product
    // into the angle times the unit normal.
    alignas(16) float angle[3][kBlock], scale[3][kBlock];
    for (std::size_t first = 0; first < count; first += kBlock) {
        const std::size_t blockSize = std::min(kBlock, count - first);
        const std::uint32_t *block = triangles + 3 * first;
        for (std::size_t i = 0; i < blockSize; ++i) {
            const glm::vec3 a = positions[block[3 * i]];
            const glm::vec3 ab = positions[block[3 * i + 1]] - a,
                            ac = positions[block[3 * i + 2]] - a;
            normal[i] = glm::cross(ab, ac);
            doubleArea[i] = std::sqrt(glm::dot(normal[i], normal[i]));
            dotA[i] = glm::dot(ab, ac);
            dotB[i] = glm::dot(ac - ab, -ab);
        }
        for (std::size_t i = 0; i < kBlock; ++i) {
            // Selects, not a guarded division: a branch would stop the
            // vectoriser (a division may trap, so it cannot be if-converted).
            // A degenerate triangle gets angles and factors 0.
            const float valid = doubleArea[i] > 0.0f ? 1.0f : 0.0f;
            const float inverse = valid / std::max(doubleArea[i], kTiny);
            angle[0][i] = angleBetween(doubleArea[i], dotA[i]);
            angle[1][i] = angleBetween(doubleArea[i], dotB[i]);
            angle[2][i] = valid * std::max(0.0f, kPi - angle[0][i] - angle[1][i]);
            scale[0][i] = angle[0][i] * inverse;
            scale[1][i] = angle[1][i] * inverse;
            scale[2][i] = angle[2][i] * inverse;
        }
        // The total grows by the angle: the length of what is added.
        for (std::size_t i = 0; i < blockSize; ++i)
            for (int k = 0; k < 3; ++k)
                sums[block[3 * i + k]] += Accumulator(scale[k][i] * normal[i], angle[k][i]);
    }
}

// Positions whose sum cancelled (faces back to back): each of their
// corners takes its own triangle's normal, which needs per-corner indices.
void splitCancelled(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                    CornerNormals &result)
{
    result.indexing = CornerNormals::Indexing::PerCorner;
    result.cornerNormal.assign(triangles.begin(), triangles.end());
    for (std::size_t c = 0; c < triangles.size(); ++c) {
        if (isZero(result.normals[triangles[c]])) {
            result.cornerNormal[c] = std::uint32_t(result.normals.size());
            result.normals.push_back(fallbackNormal(positions, triangles, c));
        }
    }
}

CornerNormals smoothNormals(std::span<const glm::vec3> positions,
                            std::span<const std::uint32_t> triangles, NormalMethod method)
{
    std::vector<Accumulator> sums(positions.size(), Accumulator(0.0f));
    const std::size_t count = triangles.size() / 3;
    if (method == NormalMethod::Average)
        accumulate<NormalMethod::Average>(positions.data(), triangles.data(), count, sums.data());
    else if (method == NormalMethod::AreaWeighted)
        accumulate<NormalMethod::AreaWeighted>(positions.data(), triangles.data(), count,
                                               sums.data());
    else
        accumulateAngleWeighted(positions.data(), triangles.data(), count, sums.data());

    CornerNormals result;
    result.indexing = CornerNormals::Indexing::PerPosition;
    result.normals.reserve(positions.size()); // filled once, not zeroed first
    bool cancelled = false;
    for (const Accumulator &sum : sums) {
        result.normals.push_back(resolve(sum));
        cancelled |= result.normals.back() == glm::vec3(0.0f);
    }
    if (cancelled)
        splitCancelled(positions, triangles, result);
    return result;
}

} // namespace

CornerNormals computeNormals(std::span<const glm::vec3> positions,
                             std::span<const std::uint32_t> triangles, NormalMethod method,
                             std::optional<double> creaseAngleDeg)
{
    if (method == NormalMethod::Flat)
        return flatNormals(positions, triangles);
    if (method == NormalMethod::Auto)
        method = NormalMethod::AngleWeighted;
    if (creaseAngleDeg)
        return CreasedNormals(positions, triangles, method, *creaseAngleDeg).run();
    return smoothNormals(positions, triangles, method);
}

std::vector<glm::vec3> expandCornerNormals(const CornerNormals &normals,
                                           std::span<const std::uint32_t> triangles)
{
    std::vector<glm::vec3> expanded(triangles.size());
    for (std::size_t c = 0; c < triangles.size(); ++c)
        expanded[c] = normals.at(c, triangles);
    return expanded;
}

} // namespace phonglab
