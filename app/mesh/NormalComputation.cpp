#include "NormalComputation.h"

#include <algorithm>
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
// (L1 norms: cheap, and within √3 of the lengths), so that a sum that
// cancelled can be told from a merely small one.
using Accumulator = glm::vec4;

glm::vec3 resolve(const Accumulator &sum)
{
    const glm::vec3 v(sum);
    const float length = std::sqrt(glm::dot(v, v));
    return length > kCancelled * sum.w && length > kTiny && length <= kHuge ? v / length : glm::vec3(0.0f);
}

// The angle atan2(y, x) for y ≥ 0, as between two edges with cross
// product length y and dot product x: accurate for tiny and near-straight
// angles, where acos of a normalised dot is not. atan on [0, 1] is a
// degree-15 odd polynomial (a Lawson-weighted least-squares fit, within
// 6e-8 rad), evaluated by Estrin's scheme for a short dependency chain; the
// octant folding uses selects, not branches, so loops of it vectorise.
// The library's atan2f took most of the angle-weighted loop's time.
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

// The normal for a corner whose own sum had no direction: its triangle's
// normal, or for a degenerate triangle one that another of its corners
// already has (`known(corner)` returns it, or null), or +Z.
template <typename Known>
glm::vec3 fallbackNormal(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                         std::size_t corner, Known known)
{
    const std::size_t base = corner - corner % 3;
    const glm::vec3 &a = positions[triangles[base]];
    const glm::vec3 face = normalizedOrZero(glm::cross(positions[triangles[base + 1]] - a,
                                                       positions[triangles[base + 2]] - a));
    if (!isZero(face))
        return face;
    for (std::size_t other = base; other < base + 3; ++other)
        if (const glm::vec3 *n = other != corner ? known(other) : nullptr)
            return *n;
    return glm::vec3(0.0f, 0.0f, 1.0f);
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
        // A degenerate triangle's corners have no neighbour to borrow from.
        result.normals[t] = isZero(n) ? glm::vec3(0.0f, 0.0f, 1.0f) : n;
    }
    return result;
}

// The hot path: scatter weighted triangle normals onto their vertices,
// then normalise once per vertex. Neighbouring triangles share vertices, so
// each scatter waits for the one before it through memory; any arithmetic
// between loading a triangle and scattering it (square roots, divisions,
// angles) would sit on that chain. So the work goes in blocks: gather the
// block's cross products, weigh them in a loop without indirection (which
// the compiler vectorises), then scatter. The method is a template
// argument so each variant compiles to its own loops.
template <NormalMethod Method>
void accumulate(const glm::vec3 *positions, const std::uint32_t *triangles, std::size_t count, Accumulator *sums)
{
    constexpr std::size_t kBlock = 256;
    glm::vec3 normal[kBlock];
    // Zeroed once: a short last block leaves stale but finite values behind.
    alignas(16) float doubleArea[kBlock] = {}, dotA[kBlock] = {}, dotB[kBlock] = {};
    // Per corner: the factor for the cross product, and what the
    // contribution adds to the total (its length).
    alignas(16) float scale[3][kBlock], size[3][kBlock];
    for (std::size_t first = 0; first < count; first += kBlock) {
        const std::size_t blockSize = std::min(kBlock, count - first);
        const std::uint32_t *block = triangles + 3 * first;
        for (std::size_t i = 0; i < blockSize; ++i) {
            const glm::vec3 a = positions[block[3 * i]];
            const glm::vec3 ab = positions[block[3 * i + 1]] - a, ac = positions[block[3 * i + 2]] - a;
            normal[i] = glm::cross(ab, ac);
            if constexpr (Method == NormalMethod::AreaWeighted) {
                // |n| is twice the area: the raw cross product is the
                // weighted normal. Its L1 norm (within √3 of its length)
                // stands in for the size, saving a square root.
                const glm::vec3 &n = normal[i];
                size[0][i] = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
            } else {
                doubleArea[i] = std::sqrt(glm::dot(normal[i], normal[i]));
            }
            if constexpr (Method == NormalMethod::AngleWeighted) {
                dotA[i] = glm::dot(ab, ac);
                dotB[i] = glm::dot(ac - ab, -ab);
            }
        }
        if constexpr (Method == NormalMethod::AreaWeighted) {
            for (std::size_t i = 0; i < blockSize; ++i) {
                const Accumulator add(normal[i], size[0][i]);
                sums[block[3 * i]] += add;
                sums[block[3 * i + 1]] += add;
                sums[block[3 * i + 2]] += add;
            }
            continue;
        }
        for (std::size_t i = 0; i < kBlock; ++i) {
            // Selects, not a guarded division: a branch would stop the
            // vectoriser (a division may trap, so it cannot be if-converted).
            // A degenerate triangle gets factor and size 0.
            const float valid = doubleArea[i] > 0.0f ? 1.0f : 0.0f;
            const float inverse = valid / std::max(doubleArea[i], kTiny);
            if constexpr (Method == NormalMethod::Average) {
                scale[0][i] = scale[1][i] = scale[2][i] = inverse;
                size[0][i] = size[1][i] = size[2][i] = valid;
            } else {
                const float atA = angleBetween(doubleArea[i], dotA[i]);
                const float atB = angleBetween(doubleArea[i], dotB[i]);
                const float atC = valid * std::max(0.0f, kPi - atA - atB);
                scale[0][i] = atA * inverse;
                scale[1][i] = atB * inverse;
                scale[2][i] = atC * inverse;
                size[0][i] = atA;
                size[1][i] = atB;
                size[2][i] = atC;
            }
        }
        for (std::size_t i = 0; i < blockSize; ++i)
            for (int k = 0; k < 3; ++k)
                sums[block[3 * i + k]] += Accumulator(scale[k][i] * normal[i], size[k][i]);
    }
}

// Positions whose sum had no direction. Their corners take fallback
// normals; where all of a position's corners agree on one (a degenerate
// triangle's corner borrowing its neighbour's), the position simply gets
// it. Only disagreement (faces back to back) costs per-corner indices.
void repairSmooth(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                  CornerNormals &result)
{
    enum : std::uint8_t { Own, Empty, Borrowed, Mixed };
    std::vector<std::uint8_t> state(result.normals.size());
    for (std::size_t v = 0; v < state.size(); ++v)
        state[v] = isZero(result.normals[v]) ? Empty : Own;
    const auto known = [&](std::size_t corner) {
        return state[triangles[corner]] == Own ? &result.normals[triangles[corner]] : nullptr;
    };
    bool mixed = false;
    for (std::size_t c = 0; c < triangles.size(); ++c) {
        const std::uint32_t v = triangles[c];
        if (state[v] == Own || state[v] == Mixed)
            continue;
        const glm::vec3 n = fallbackNormal(positions, triangles, c, known);
        if (state[v] == Empty) {
            result.normals[v] = n;
            state[v] = Borrowed;
        } else if (n != result.normals[v]) {
            state[v] = Mixed;
            mixed = true;
        }
    }
    if (!mixed)
        return;
    result.indexing = CornerNormals::Indexing::PerCorner;
    result.cornerNormal.assign(triangles.begin(), triangles.end());
    for (std::size_t c = 0; c < triangles.size(); ++c) {
        if (state[triangles[c]] == Mixed) {
            result.cornerNormal[c] = std::uint32_t(result.normals.size());
            result.normals.push_back(fallbackNormal(positions, triangles, c, known));
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
        accumulate<NormalMethod::AngleWeighted>(positions.data(), triangles.data(), count, sums.data());

    CornerNormals result;
    result.indexing = CornerNormals::Indexing::PerPosition;
    result.normals.resize(positions.size());
    std::size_t zeros = 0; // includes positions no triangle uses
    for (std::size_t v = 0; v < sums.size(); ++v) {
        result.normals[v] = resolve(sums[v]);
        zeros += isZero(result.normals[v]);
    }
    if (zeros != 0)
        repairSmooth(positions, triangles, result);
    return result;
}

// Smoothing groups split at sharp edges. Each vertex's corners come from a
// CSR adjacency; two corners whose triangles share an edge at the vertex
// and meet at no more than the crease angle are joined with a tiny
// union-find; each group gets one normal.
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
    // Above this many corners at a vertex, edges are matched by sorting
    // rather than by comparing every pair.
    static constexpr std::uint32_t kPairwiseLimit = 24;

    void computeFaces();
    void buildAdjacency();
    void solveVertex(const std::uint32_t *corners, std::uint32_t count, CornerNormals &result);
    void joinIfSmooth(std::uint32_t i, std::uint32_t j)
    {
        // A degenerate triangle has no direction to disagree with.
        const Corner &a = m_corners[i], &b = m_corners[j];
        if (a.degenerate || b.degenerate || glm::dot(a.unit, b.unit) >= m_cosCrease)
            m_corners[find(i)].parent = find(j);
    }
    float weight(std::uint32_t corner) const;
    std::uint32_t find(std::uint32_t j)
    {
        while (m_corners[j].parent != j)
            j = m_corners[j].parent = m_corners[m_corners[j].parent].parent;
        return j;
    }

    std::span<const glm::vec3> m_positions;
    std::span<const std::uint32_t> m_triangles;
    NormalMethod m_method;
    float m_cosCrease;

    std::vector<glm::vec3> m_faceUnit; // zero for degenerate triangles
    std::vector<float> m_faceDoubleArea;
    std::vector<std::uint32_t> m_vertexStart;   // CSR: corners of vertex v are
    std::vector<std::uint32_t> m_vertexCorners; // m_vertexCorners[m_vertexStart[v] ..]

    // Per-vertex scratch, reused: the vertex's corners, gathered once.
    struct Corner {
        std::uint32_t next, prev; // the triangle's other two positions
        std::uint32_t parent;     // union-find
        bool degenerate;
        glm::vec3 unit;           // the triangle's normal
    };
    std::vector<Corner> m_corners;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> m_edges; // (other position, local corner)
    std::vector<Accumulator> m_groupSum;
    std::vector<std::uint32_t> m_groupNormal;
    std::vector<std::uint32_t> m_unresolved; // corners whose group cancelled
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
        m_faceDoubleArea[t] = isZero(m_faceUnit[t]) ? 0.0f : std::sqrt(glm::dot(n, n));
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

void CreasedNormals::solveVertex(const std::uint32_t *corners, std::uint32_t count, CornerNormals &result)
{
    m_corners.resize(count);
    for (std::uint32_t j = 0; j < count; ++j) {
        const std::uint32_t c = corners[j], k = c % 3, base = c - k;
        const glm::vec3 &unit = m_faceUnit[c / 3];
        m_corners[j] = {m_triangles[base + (k == 2 ? 0 : k + 1)], m_triangles[base + (k == 0 ? 2 : k - 1)], j,
                        isZero(unit), unit};
    }

    // Two corners meet across an edge when their triangles have the same
    // other endpoint there (matched either way round, so a flipped
    // neighbour still counts as adjacent; its normal keeps it apart).
    if (count <= kPairwiseLimit) {
        for (std::uint32_t j = 1; j < count; ++j) {
            const Corner &b = m_corners[j];
            for (std::uint32_t i = 0; i < j; ++i) {
                const Corner &a = m_corners[i];
                if (a.next == b.prev || a.prev == b.next || a.next == b.next || a.prev == b.prev)
                    joinIfSmooth(i, j);
            }
        }
    } else {
        // Big fans (a pole, a cone's tip): sort (endpoint, corner) pairs
        // instead; non-manifold edges give longer runs, all pairs join.
        m_edges.clear();
        for (std::uint32_t j = 0; j < count; ++j) {
            m_edges.emplace_back(m_corners[j].next, j);
            m_edges.emplace_back(m_corners[j].prev, j);
        }
        std::sort(m_edges.begin(), m_edges.end());
        for (std::size_t s = 0, e = 0; s < m_edges.size(); s = e) {
            while (e < m_edges.size() && m_edges[e].first == m_edges[s].first)
                ++e;
            for (std::size_t x = s; x < e; ++x)
                for (std::size_t y = x + 1; y < e; ++y)
                    if (m_edges[x].second != m_edges[y].second)
                        joinIfSmooth(m_edges[x].second, m_edges[y].second);
        }
    }

    m_groupSum.assign(count, Accumulator(0.0f));
    for (std::uint32_t j = 0; j < count; ++j) {
        const glm::vec3 &unit = m_corners[j].unit;
        m_groupSum[find(j)] += weight(corners[j]) * Accumulator(unit, sizeOf(unit));
    }
    m_groupNormal.assign(count, kUnassigned);
    for (std::uint32_t j = 0; j < count; ++j) {
        const std::uint32_t root = find(j);
        std::uint32_t &index = m_groupNormal[root];
        if (index == kUnassigned) {
            const glm::vec3 n = resolve(m_groupSum[root]);
            if (isZero(n)) {
                // The group cancels out: each corner falls back on its own,
                // once all the others have their normals to borrow.
                result.cornerNormal[corners[j]] = kUnassigned;
                m_unresolved.push_back(corners[j]);
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
    const auto known = [&](std::size_t corner) {
        const std::uint32_t index = result.cornerNormal[corner];
        return index != kUnassigned ? &result.normals[index] : nullptr;
    };
    for (std::uint32_t c : m_unresolved) {
        const glm::vec3 n = fallbackNormal(m_positions, m_triangles, c, known);
        result.cornerNormal[c] = std::uint32_t(result.normals.size());
        result.normals.push_back(n);
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
