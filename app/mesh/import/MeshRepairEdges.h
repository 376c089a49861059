#pragma once
// Internal to MeshRepair*.cpp: the repair steps that work along edges, which
// MeshRepairEdges.cpp holds: the edge adjacency, the winding made to agree
// across manifold edges, and the vertices split where surfaces touch at a
// point. MeshRepair.cpp runs them between its per-face steps.
#include "MeshRepair.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace phonglab::repair {

constexpr std::uint32_t kUnset = 0xffffffffu;

// Edge adjacency: every face side, grouped by its undirected edge.
struct Side {
    std::uint32_t other; // the larger vertex index of the edge
    std::uint32_t face;
    std::uint32_t corner; // the corner the side starts at
    bool forward;         // runs from the smaller vertex to the larger
};

struct Adjacency {
    std::vector<std::uint32_t> cornerFace;
    std::vector<std::uint32_t> bucketStart; // per smaller vertex, into sides
    std::vector<Side> sides;                // within a bucket sorted by `other`
};

Adjacency buildAdjacency(const PolygonMesh &mesh);

// Calls visit(first, count) for each run of sides sharing an edge.
template <typename Visit> void forEachEdge(const Adjacency &adj, Visit visit)
{
    const std::size_t n = adj.sides.size();
    for (std::size_t v = 0; v + 1 < adj.bucketStart.size(); ++v) {
        for (std::size_t i = adj.bucketStart[v]; i < adj.bucketStart[v + 1];) {
            std::size_t j = i + 1;
            while (j < n && j < adj.bucketStart[v + 1] && adj.sides[j].other == adj.sides[i].other)
                ++j;
            visit(i, j - i);
            i = j;
        }
    }
}

// Which faces to turn so the winding agrees across manifold edges. Reads
// the mesh, changes nothing: it runs beside bowtieGroups().
std::vector<char> windingFlips(const PolygonMesh &mesh, const Adjacency &adj, RepairReport &report);
void flipFaces(PolygonMesh &mesh, const std::vector<char> &flip, RepairReport &report);

// Corners of one vertex belong together when their faces share an edge at
// that vertex (any edge of 2+ faces, non-manifold ones included). Returns a
// union-find forest over the corners. Reads the mesh, changes nothing: it
// runs beside windingFlips().
std::vector<std::uint32_t> bowtieGroups(const PolygonMesh &mesh, const Adjacency &adj);
// More than one group of corners at a vertex: surfaces touching at a point
// only. Every group after the first gets its own copy of the vertex.
void splitBowtieVertices(PolygonMesh &mesh, std::vector<std::uint32_t> &parent,
                         RepairReport &report);

} // namespace phonglab::repair
