#include "MeshTopology.h"

#include <algorithm>

namespace phonglab {

bool isClosedSurface(const PolygonMesh &mesh)
{
    if (mesh.faceCount() == 0)
        return false;
    // Each undirected edge as one 64-bit key; sorted, a closed surface shows
    // every key exactly twice.
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

} // namespace phonglab
