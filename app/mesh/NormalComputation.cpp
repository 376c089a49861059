#include "NormalComputation.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <utility>

namespace phonglab {

namespace {

constexpr std::uint32_t kUnassigned = std::numeric_limits<std::uint32_t>::max();
constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kTiny = std::numeric_limits<float>::min();
constexpr float kHuge = std::numeric_limits<float>::max();
// A sum shorter than this fraction of its parts' total size has cancelled:
// its direction is rounding noise (two faces back to back, or within
// 0.01° of it), not a normal.
constexpr float kCancelled = 1e-4f;

// Unit vector along v, or zero when v has no usable direction. Dividing by
// the length (rather than multiplying by its inverse) keeps axis-aligned
// normals exact: sqrt(w²) is w in IEEE arithmetic, and w / w is 1.
glm::vec3 normalizedOrZero(const glm::vec3 &v)
{
    const float length = std::sqrt(glm::dot(v, v));
    return length > kTiny && length <= kHuge ? v / length : glm::vec3(0.0f);
}

bool isZero(const glm::vec3 &v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; }

float sizeOf(const glm::vec3 &v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }

// A weighted normal sum in xyz and, in w, the total size of what was added
// (the lengths, or for raw cross products their L1 norms: cheaper, and
// within √3), so that a sum that cancelled can be told from a small one.
using Accumulator = glm::vec4;

constexpr glm::vec3 kLastResort(0.0f, 0.0f, 1.0f);

// The unit normal a sum stands for. A sum of nothing (a position only
// degenerate triangles touch, which are invisible, or none) gets the last
// resort, +Z. A sum that cancelled gives zero: its corners need their
// triangles' normals instead.
inline glm::vec3 resolve(const Accumulator &sum)
{
    if (sum.w == 0.0f)
        return kLastResort;
    const glm::vec3 v(sum);
    const float length = std::sqrt(glm::dot(v, v));
    return length > kCancelled * sum.w && length > kTiny && length <= kHuge ? v / length : glm::vec3(0.0f);
}

// The angle atan2(y, x) for y ≥ 0, as between two edges with cross
// product length y and dot product x: accurate for tiny and near-straight
// angles, where acos of a normalised dot is not. atan on [0, 1] is a
// degree-15 odd polynomial (a Lawson-weighted least-squares fit within
// 6e-8), evaluated by Estrin's scheme for a short dependency chain; the
// octant folding uses selects, not branches, so loops of it vectorise.
// Within 4e-7 rad of the exact angle; the library's atan2f, in its place,
// took most of the angle-weighted loop's time.
inline float angleBetween(float y, float x)
{
    const float ax = std::abs(x);
    const float lo = std::min(ax, y), hi = std::max(ax, y);
    const float t = lo / std::max(hi, kTiny);
    const float z = t * t, z2 = z * z, z4 = z2 * z2;
    const float atanT = t * ((0.999999336f - 0.333298608f * z) + z2 * (0.199465661f - 0.139086307f * z)
        + z4 * ((0.0964219876f - 0.0559123329f * z) + z2 * (0.0218629554f - 0.00405456518f * z)));
    const float steep = y > ax ? 1.0f : 0.0f, obtuse = x < 0.0f ? 1.0f : 0.0f;
    const float acute = steep * (kPi / 2) + (1.0f - 2.0f * steep) * atanT;
    return obtuse * kPi + (1.0f - 2.0f * obtuse) * acute;
}

// The normal for a corner whose own sum cancelled: its triangle's.
glm::vec3 fallbackNormal(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                         std::size_t corner)
{
    const std::size_t base = corner - corner % 3;
    const glm::vec3 &a = positions[triangles[base]];
    const glm::vec3 face = normalizedOrZero(glm::cross(positions[triangles[base + 1]] - a,
                                                       positions[triangles[base + 2]] - a));
    return isZero(face) ? kLastResort : face;
}

CornerNormals flatNormals(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles)
{
    CornerNormals result;
    result.indexing = CornerNormals::Indexing::PerTriangle;
    const std::size_t count = triangles.size() / 3;
    result.normals.resize(count);
    for (std::size_t t = 0; t < count; ++t) {
        const glm::vec3 &a = positions[triangles[3 * t]];
        const glm::vec3 n = normalizedOrZero(glm::cross(positions[triangles[3 * t + 1]] - a,
                                                        positions[triangles[3 * t + 2]] - a));
        // A degenerate triangle is invisible; any normal will do.
        result.normals[t] = isZero(n) ? kLastResort : n;
    }
    return result;
}

// The hot path: one pass scattering weighted triangle normals onto their
// vertices, then one normalising each vertex's sum. The method is a
// template argument so each variant compiles to its own tight loop.
template <NormalMethod Method>
void accumulate(const glm::vec3 *positions, const std::uint32_t *triangles, std::size_t count, Accumulator *sums)
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
void accumulateAngleWeighted(const glm::vec3 *positions, const std::uint32_t *triangles, std::size_t count,
                             Accumulator *sums)
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
            const glm::vec3 ab = positions[block[3 * i + 1]] - a, ac = positions[block[3 * i + 2]] - a;
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

CornerNormals smoothNormals(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                            NormalMethod method)
{
    std::vector<Accumulator> sums(positions.size(), Accumulator(0.0f));
    const std::size_t count = triangles.size() / 3;
    if (method == NormalMethod::Average)
        accumulate<NormalMethod::Average>(positions.data(), triangles.data(), count, sums.data());
    else if (method == NormalMethod::AreaWeighted)
        accumulate<NormalMethod::AreaWeighted>(positions.data(), triangles.data(), count, sums.data());
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

// Smoothing groups split at sharp edges. Each vertex's corners come from a
// CSR adjacency; corners whose triangles share an edge at the vertex and
// meet at no more than the crease angle are connected, and each connected
// group of corners gets one normal.
class CreasedNormals {
public:
    CreasedNormals(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                   NormalMethod method, double creaseAngleDeg)
        : m_positions(positions), m_triangles(triangles), m_method(method),
          // The small slack lets faces at exactly the crease angle (a
          // cube's 90° with a 90° crease) join despite rounding.
          m_cosCrease(float(std::cos(std::clamp(creaseAngleDeg, 0.0, 180.0) * std::numbers::pi / 180.0)) - 1e-6f) {}

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
        glm::vec3 unit;           // the triangle's normal
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

void CreasedNormals::computeFaces()
{
    const std::size_t count = m_triangles.size() / 3;
    m_faceUnit.resize(count);
    m_faceDoubleArea.resize(count);
    for (std::size_t t = 0; t < count; ++t) {
        const glm::vec3 &a = m_positions[m_triangles[3 * t]];
        const glm::vec3 n = glm::cross(m_positions[m_triangles[3 * t + 1]] - a, m_positions[m_triangles[3 * t + 2]] - a);
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
            if ((a.next == b.prev || a.prev == b.next || a.next == b.next || a.prev == b.prev) && smooth(a, b)) {
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

void CreasedNormals::solveVertex(const std::uint32_t *corners, std::uint32_t count, CornerNormals &result)
{
    m_corners.resize(count);
    for (std::uint32_t j = 0; j < count; ++j) {
        const std::uint32_t c = corners[j], k = c % 3, base = c - k;
        const glm::vec3 &unit = m_faceUnit[c / 3];
        m_corners[j] = {m_triangles[base + (k == 2 ? 0 : k + 1)], m_triangles[base + (k == 0 ? 2 : k - 1)], 0,
                        isZero(unit), unit};
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

} // namespace

CornerNormals computeNormals(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                             NormalMethod method, std::optional<double> creaseAngleDeg)
{
    if (method == NormalMethod::Flat)
        return flatNormals(positions, triangles);
    if (method == NormalMethod::Auto)
        method = NormalMethod::AngleWeighted;
    if (creaseAngleDeg)
        return CreasedNormals(positions, triangles, method, *creaseAngleDeg).run();
    return smoothNormals(positions, triangles, method);
}

std::vector<glm::vec3> expandCornerNormals(const CornerNormals &normals, std::span<const std::uint32_t> triangles)
{
    std::vector<glm::vec3> expanded(triangles.size());
    for (std::size_t c = 0; c < triangles.size(); ++c)
        expanded[c] = normals.at(c, triangles);
    return expanded;
}

} // namespace phonglab
