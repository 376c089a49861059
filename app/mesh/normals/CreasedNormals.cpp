#include "CreasedNormals.h"

#include "NormalMath.h"

#include <numeric>
#include <utility>

namespace phonglab::normals {

void CreasedNormals::computeFaces()
{
    const std::size_t count = m_triangles.size() / 3;
    m_faceUnit.resize(count);
    m_faceDoubleArea.resize(count);
    for (std::size_t t = 0; t < count; ++t) {
        const glm::vec3 &a = m_positions[m_triangles[3 * t]];
        const glm::vec3 n = glm::cross(m_positions[m_triangles[3 * t + 1]] - a,
                                       m_positions[m_triangles[3 * t + 2]] - a);
        m_faceUnit[t] = normalizedOrZero(n);
        m_faceDoubleArea[t] = isZero(m_faceUnit[t]) ? 0.0f : glm::dot(n, m_faceUnit[t]);
    }
}

void CreasedNormals::buildAdjacency()
{
    m_vertexStart.assign(m_positions.size() + 1, 0);
    for (std::uint32_t v : m_triangles)
        ++m_vertexStart[v + 1];
    std::partial_sum(m_vertexStart.begin(), m_vertexStart.end(), m_vertexStart.begin());
    m_vertexCorners.resize(m_triangles.size());
    std::vector<std::uint32_t> cursor(m_vertexStart.begin(), m_vertexStart.end() - 1);
    for (std::uint32_t c = 0; c < m_triangles.size(); ++c)
        m_vertexCorners[cursor[m_triangles[c]]++] = c;
}

float CreasedNormals::weight(std::uint32_t corner) const
{
    const std::uint32_t t = corner / 3;
    if (m_method == NormalMethod::Average)
        return 1.0f;
    if (m_method == NormalMethod::AreaWeighted)
        return m_faceDoubleArea[t];
    const std::uint32_t base = 3 * t, k = corner - base;
    const glm::vec3 &p = m_positions[m_triangles[corner]];
    const glm::vec3 &q = m_positions[m_triangles[base + (k + 1) % 3]];
    const glm::vec3 &r = m_positions[m_triangles[base + (k + 2) % 3]];
    return angleBetween(m_faceDoubleArea[t], glm::dot(q - p, r - p));
}

std::uint32_t CreasedNormals::groupSmallFan(std::uint32_t count)
{
    // Bit i of adjacent[j]: corners i and j meet across a smooth edge.
    std::uint32_t adjacent[kSmallFan] = {};
    for (std::uint32_t j = 1; j < count; ++j) {
        const Corner &b = m_corners[j];
        for (std::uint32_t i = 0; i < j; ++i) {
            const Corner &a = m_corners[i];
            if ((a.next == b.prev || a.prev == b.next || a.next == b.next || a.prev == b.prev)
                && smooth(a, b)) {
                adjacent[i] |= 1u << j;
                adjacent[j] |= 1u << i;
            }
        }
    }
    // Flood fill over the bit sets, one group at a time.
    std::uint32_t remaining = count == 32 ? ~0u : (1u << count) - 1;
    std::uint32_t groups = 0;
    while (remaining != 0) {
        std::uint32_t group = remaining & (~remaining + 1), frontier = group;
        while (frontier != 0) {
            const std::uint32_t fresh = adjacent[std::countr_zero(frontier)] & ~group;
            frontier = (frontier & (frontier - 1)) | fresh;
            group |= fresh;
        }
        remaining &= ~group;
        for (; group != 0; group &= group - 1)
            m_corners[std::countr_zero(group)].group = groups;
        ++groups;
    }
    return groups;
}

std::uint32_t CreasedNormals::groupLargeFan(std::uint32_t count)
{
    // Union-find over edges matched by sorting (endpoint, corner) pairs;
    // non-manifold edges give runs longer than two, all pairs join.
    std::vector<std::uint32_t> &parent = m_parent;
    parent.resize(count);
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&](std::uint32_t j) {
        while (parent[j] != j)
            j = parent[j] = parent[parent[j]];
        return j;
    };
    m_edges.clear();
    for (std::uint32_t j = 0; j < count; ++j) {
        m_edges.emplace_back(m_corners[j].next, j);
        m_edges.emplace_back(m_corners[j].prev, j);
    }
    std::sort(m_edges.begin(), m_edges.end());
    for (std::size_t s = 0, e = 0; s < m_edges.size(); s = e) {
        while (e < m_edges.size() && m_edges[e].first == m_edges[s].first)
            ++e;
        for (std::size_t x = s; x < e; ++x) {
            for (std::size_t y = x + 1; y < e; ++y) {
                const std::uint32_t i = m_edges[x].second, j = m_edges[y].second;
                if (i != j && smooth(m_corners[i], m_corners[j]))
                    parent[find(i)] = find(j);
            }
        }
    }
    // Number the roots 0, 1, ... in order of first appearance.
    std::uint32_t groups = 0;
    for (std::uint32_t j = 0; j < count; ++j)
        m_corners[j].group = kUnassigned;
    for (std::uint32_t j = 0; j < count; ++j) {
        Corner &root = m_corners[find(j)];
        if (root.group == kUnassigned)
            root.group = groups++;
        m_corners[j].group = root.group;
    }
    return groups;
}

void CreasedNormals::solveVertex(const std::uint32_t *corners, std::uint32_t count,
                                 CornerNormals &result)
{
    m_corners.resize(count);
    for (std::uint32_t j = 0; j < count; ++j) {
        const std::uint32_t c = corners[j], k = c % 3, base = c - k;
        const glm::vec3 &unit = m_faceUnit[c / 3];
        m_corners[j] = {m_triangles[base + (k == 2 ? 0 : k + 1)],
                        m_triangles[base + (k == 0 ? 2 : k - 1)], 0, isZero(unit), unit};
    }
    // Two corners meet across an edge when their triangles have the same
    // other endpoint there (matched either way round, so a flipped
    // neighbour still counts as adjacent; its normal keeps it apart).
    const std::uint32_t groups = count <= kSmallFan ? groupSmallFan(count) : groupLargeFan(count);

    m_groupSum.assign(groups, Accumulator(0.0f));
    for (std::uint32_t j = 0; j < count; ++j) {
        const glm::vec3 &unit = m_corners[j].unit;
        m_groupSum[m_corners[j].group] += weight(corners[j]) * Accumulator(unit, sizeOf(unit));
    }
    m_groupNormal.assign(groups, kUnassigned);
    for (std::uint32_t j = 0; j < count; ++j) {
        std::uint32_t &index = m_groupNormal[m_corners[j].group];
        if (index == kUnassigned) {
            const glm::vec3 n = resolve(m_groupSum[m_corners[j].group]);
            if (isZero(n)) {
                // The group cancels out: each corner takes its triangle's.
                result.cornerNormal[corners[j]] = std::uint32_t(result.normals.size());
                result.normals.push_back(fallbackNormal(m_positions, m_triangles, corners[j]));
                continue;
            }
            index = std::uint32_t(result.normals.size());
            result.normals.push_back(n);
        }
        result.cornerNormal[corners[j]] = index;
    }
}

CornerNormals CreasedNormals::run()
{
    computeFaces();
    buildAdjacency();
    CornerNormals result;
    result.cornerNormal.resize(m_triangles.size());
    result.normals.reserve(m_positions.size() + m_positions.size() / 4);
    for (std::size_t v = 0; v + 1 < m_vertexStart.size(); ++v) {
        const std::uint32_t first = m_vertexStart[v], count = m_vertexStart[v + 1] - first;
        if (count != 0)
            solveVertex(m_vertexCorners.data() + first, count, result);
    }
    return result;
}

} // namespace phonglab::normals
