#pragma once
#include "NormalComputation.h"
#include "NormalMath.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

namespace phonglab::normals {

// Smoothing groups split at sharp edges. Each vertex's corners come from a
// CSR adjacency; corners whose triangles share an edge at the vertex and
// meet at no more than the crease angle are connected, and each connected
// group of corners gets one normal.
class CreasedNormals
{
public:
    CreasedNormals(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                   NormalMethod method, double creaseAngleDeg)
        : m_positions(positions)
        , m_triangles(triangles)
        , m_method(method)
        ,
        // The small slack lets faces at exactly the crease angle (a
        // cube's 90° with a 90° crease) join despite rounding.
        m_cosCrease(
            float(std::cos(std::clamp(creaseAngleDeg, 0.0, 180.0) * std::numbers::pi / 180.0))
            - 1e-6f)
    {
    }

    CornerNormals run();

private:
    // Up to this many corners at a vertex, edges are matched by comparing
    // every pair and groups found over 32-bit sets; above (poles, cone
    // tips), by sorting and union-find.
    static constexpr std::uint32_t kSmallFan = 32;

    struct Corner {
        std::uint32_t next, prev; // the triangle's other two positions
        std::uint32_t group;      // smoothing group, numbered from 0 per vertex
        bool degenerate;
        glm::vec3 unit; // the triangle's normal
    };

    void computeFaces();
    void buildAdjacency();
    void solveVertex(const std::uint32_t *corners, std::uint32_t count, CornerNormals &result);
    std::uint32_t groupSmallFan(std::uint32_t count);
    std::uint32_t groupLargeFan(std::uint32_t count);
    bool smooth(const Corner &a, const Corner &b) const
    {
        // A degenerate triangle has no direction to disagree with.
        return a.degenerate || b.degenerate || glm::dot(a.unit, b.unit) >= m_cosCrease;
    }
    float weight(std::uint32_t corner) const;

    std::span<const glm::vec3> m_positions;
    std::span<const std::uint32_t> m_triangles;
    NormalMethod m_method;
    float m_cosCrease;

    std::vector<glm::vec3> m_faceUnit; // zero for degenerate triangles
    std::vector<float> m_faceDoubleArea;
    std::vector<std::uint32_t> m_vertexStart;   // CSR: corners of vertex v are
    std::vector<std::uint32_t> m_vertexCorners; // m_vertexCorners[m_vertexStart[v] ..]

    // Per-vertex scratch, reused: the vertex's corners, gathered once.
    std::vector<Corner> m_corners;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> m_edges; // (other position, local corner)
    std::vector<std::uint32_t> m_parent;
    std::vector<Accumulator> m_groupSum;
    std::vector<std::uint32_t> m_groupNormal;
};

} // namespace phonglab::normals
