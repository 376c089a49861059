#include "MeshTopology.h"

#include <algorithm>
#include <numeric>

namespace phonglab {

namespace {

// Buckets small enough for an insertion sort; a vertex of a triangle mesh
// is the smaller end of about three edges, six face sides.
constexpr std::size_t kSmallBucket = 32;

void sortBucket(std::uint32_t *begin, std::uint32_t *end)
{
    if (std::size_t(end - begin) > kSmallBucket) {
        std::sort(begin, end);
        return;
    }
    for (std::uint32_t *i = begin + 1; i < end; ++i) {
        const std::uint32_t v = *i;
        std::uint32_t *j = i;
        for (; j > begin && j[-1] > v; --j)
            *j = j[-1];
        *j = v;
    }
}

// Sorted, every value must appear exactly twice.
bool eachValueTwice(const std::uint32_t *begin, const std::uint32_t *end)
{
    if ((end - begin) % 2 != 0)
        return false;
    for (const std::uint32_t *p = begin; p < end; p += 2)
        if (p[0] != p[1] || (p + 2 < end && p[2] == p[0]))
            return false;
    return true;
}

// For corner indices beyond `positions` (a mesh not yet repaired), where
// buckets per vertex could not be afforded: each undirected edge as one
// 64-bit key, sorted.
bool closedBySorting(const PolygonMesh &mesh)
{
    std::vector<std::uint64_t> edges;
    edges.reserve(mesh.cornerPosition.size());
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
        const std::uint32_t begin = mesh.faceStart[f], end = mesh.faceStart[f + 1];
        for (std::uint32_t c = begin; c < end; ++c) {
            std::uint64_t a = mesh.cornerPosition[c];
            std::uint64_t b = mesh.cornerPosition[c + 1 < end ? c + 1 : begin];
            if (a > b)
                std::swap(a, b);
            edges.push_back((a << 32) | b);
        }
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i])
            ++j;
        if (j - i != 2)
            return false;
        i = j;
    }
    return true;
}

} // namespace

bool isClosedSurface(const PolygonMesh &mesh)
{
    if (mesh.faceCount() == 0)
        return false;
    const bool inRange = std::all_of(mesh.cornerPosition.begin(), mesh.cornerPosition.end(),
                                     [&](std::uint32_t v) { return v < mesh.positions.size(); });
    if (!inRange)
        return closedBySorting(mesh);
    // Every face side filed under its smaller vertex (a counting sort, linear
    // time: sorting all edges as one array took a third of an import), then
    // within each vertex's bucket every larger vertex must appear exactly
    // twice.
    std::vector<std::uint32_t> bucketStart(mesh.positions.size() + 1, 0);
    auto forEachSide = [&mesh](auto visit) {
        for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
            const std::uint32_t begin = mesh.faceStart[f], end = mesh.faceStart[f + 1];
            for (std::uint32_t c = begin; c < end; ++c) {
                const std::uint32_t a = mesh.cornerPosition[c];
                const std::uint32_t b = mesh.cornerPosition[c + 1 < end ? c + 1 : begin];
                visit(std::min(a, b), std::max(a, b));
            }
        }
    };
    forEachSide([&](std::uint32_t small, std::uint32_t) { ++bucketStart[std::size_t(small) + 1]; });
    std::partial_sum(bucketStart.begin(), bucketStart.end(), bucketStart.begin());
    std::vector<std::uint32_t> larger(bucketStart.back());
    std::vector<std::uint32_t> fill(bucketStart.begin(), bucketStart.end() - 1);
    forEachSide([&](std::uint32_t small, std::uint32_t large) { larger[fill[small]++] = large; });
    for (std::size_t v = 0; v + 1 < bucketStart.size(); ++v) {
        std::uint32_t *begin = larger.data() + bucketStart[v];
        std::uint32_t *end = larger.data() + bucketStart[v + 1];
        sortBucket(begin, end);
        if (!eachValueTwice(begin, end))
            return false;
    }
    return true;
}

} // namespace phonglab
