#include "core/reference/MeshBvh.h"

#include <QtGlobal>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace phonglab {

namespace {

// --- Triangle test -----------------------------------------------------------

// The per-ray part of the watertight test: the ray is sheared so that it runs
// along +z from the origin; only the shear depends on the ray, so it is
// computed once per ray, not once per triangle.
struct ShearedRay {
    glm::dvec3 origin{0.0};
    int kx = 0, ky = 1, kz = 2; // kz: the direction's dominant axis
    double sx = 0.0, sy = 0.0, sz = 1.0;
    bool valid = false; // false for a zero direction: it hits nothing

    explicit ShearedRay(const Ray &ray)
        : origin(ray.origin)
    {
        const glm::dvec3 a = glm::abs(ray.direction);
        kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
        if (!(a[kz] > 0.0))
            return;
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        // Keep the winding of the sheared triangle the same as seen along +z.
        if (ray.direction[kz] < 0.0)
            std::swap(kx, ky);
        sx = ray.direction[kx] / ray.direction[kz];
        sy = ray.direction[ky] / ray.direction[kz];
        sz = 1.0 / ray.direction[kz];
        valid = true;
    }
};

// Ray against one triangle, both faces (no culling), in double precision
// with the watertight test of Woop, Benthin and Wald (JCGT 2013): the edge
// functions of an edge two triangles share are computed from the same
// transformed vertices, so they are exact negatives of each other and a ray
// cannot slip between two triangles of a closed mesh. Degenerate (zero-area
// as seen along the ray) triangles are never hit. Hits with t in [tMin, tMax].
std::optional<TriangleHit> intersectSheared(const ShearedRay &r, const glm::dvec3 &v0,
                                            const glm::dvec3 &v1, const glm::dvec3 &v2, double tMin,
                                            double tMax)
{
    if (!r.valid)
        return std::nullopt;
    const glm::dvec3 a = v0 - r.origin, b = v1 - r.origin, c = v2 - r.origin;
    const double ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
    const double bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
    const double cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
    // Edge functions: u for edge (v1, v2), i.e. the weight of v0, and so on.
    // Each is computed from its edge's two vertices alone, so the triangle
    // on the other side of a shared edge gets exactly -u: no gaps, no
    // double coverage beyond the edge itself.
    const double u = cx * by - cy * bx;
    const double v = ax * cy - ay * cx;
    const double w = bx * ay - by * ax;
    // Both faces: inside when all three have the same sign (zeros allowed,
    // a hit exactly on an edge counts).
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0))
        return std::nullopt;
    const double det = u + v + w;
    if (det == 0.0)
        return std::nullopt; // edge-on or degenerate: no area to hit
    const double tScaled = u * (r.sz * a[r.kz]) + v * (r.sz * b[r.kz]) + w * (r.sz * c[r.kz]);
    const double t = tScaled / det;
    if (!(t >= tMin && t <= tMax))
        return std::nullopt;
    const double inv = 1.0 / det;
    return TriangleHit{t, 0, glm::dvec3(u * inv, v * inv, w * inv)};
}

// Nearer, or equally near and a lower triangle index: the order-independent
// choice that makes the BVH and the brute force agree exactly.
bool better(const TriangleHit &candidate, const std::optional<TriangleHit> &best)
{
    return !best || candidate.t < best->t
        || (candidate.t == best->t && candidate.triangle < best->triangle);
}

// --- Build -------------------------------------------------------------------

struct Box {
    glm::vec3 lo{std::numeric_limits<float>::infinity()};
    glm::vec3 hi{-std::numeric_limits<float>::infinity()};

    void grow(const glm::vec3 &p)
    {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void grow(const Box &b)
    {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool empty() const { return lo.x > hi.x; }
    // Half the surface area: SAH only compares areas, the factor 2 cancels.
    double halfArea() const
    {
        if (empty())
            return 0.0;
        const glm::dvec3 e = glm::dvec3(hi) - glm::dvec3(lo);
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

constexpr int kBins = 16;
constexpr int kMaxLeafSize = 8;        // larger ranges are always split
constexpr double kTraversalCost = 1.0; // relative to one triangle test
// Below this depth the builder splits by SAH; deeper (pathological input
// only) it splits at the median, which halves the range every level, so the
// tree depth, and the traversal stack, stay bounded.
constexpr int kSahDepth = 64;
constexpr int kMaxDepth = kSahDepth + 33;

struct BuildTask {
    std::uint32_t node = 0;
    std::uint32_t begin = 0, end = 0;
    int depth = 0;
};

struct Split {
    int axis = -1;
    int bin = 0; // triangles in bins [0, bin] go left
    double cost = std::numeric_limits<double>::infinity();
};

// The cheapest binned-SAH split of triangles [begin, end) over all three axes.
Split bestSahSplit(const std::vector<std::uint32_t> &order, std::uint32_t begin, std::uint32_t end,
                   const std::vector<Box> &boxes, const std::vector<glm::vec3> &centroids,
                   const Box &centroidBounds, double parentArea)
{
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = centroidBounds.lo[axis], extent = double(centroidBounds.hi[axis]) - lo;
        if (!(extent > 0.0))
            continue; // all centroids in one plane across this axis: nothing to separate
        const double scale = kBins / extent;
        std::array<Box, kBins> binBoxes{};
        std::array<std::uint32_t, kBins> binCounts{};
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::uint32_t tri = order[i];
            const int bin = std::min(int((centroids[tri][axis] - lo) * scale), kBins - 1);
            binBoxes[bin].grow(boxes[tri]);
            ++binCounts[bin];
        }
        // Sweep from the right to get every right-hand side, then from the left.
        std::array<double, kBins> rightArea{};
        std::array<std::uint32_t, kBins> rightCount{};
        Box right;
        std::uint32_t count = 0;
        for (int b = kBins - 1; b > 0; --b) {
            right.grow(binBoxes[b]);
            count += binCounts[b];
            rightArea[b] = right.halfArea();
            rightCount[b] = count;
        }
        Box left;
        count = 0;
        for (int b = 0; b < kBins - 1; ++b) {
            left.grow(binBoxes[b]);
            count += binCounts[b];
            if (count == 0 || rightCount[b + 1] == 0)
                continue;
            const double cost = kTraversalCost
                + (left.halfArea() * count + rightArea[b + 1] * rightCount[b + 1]) / parentArea;
            if (cost < best.cost)
                best = Split{axis, b, cost};
        }
    }
    return best;
}

// The per-triangle input of the build, indexed by mesh triangle; `order`
// is the permutation the build sorts into the BVH's triangle order.
struct BuildInput {
    std::vector<Box> boxes;
    std::vector<glm::vec3> centroids;
    std::vector<std::uint32_t> order;
};

BuildInput triangleBounds(const MeshData &mesh, std::uint32_t n)
{
    BuildInput in{std::vector<Box>(n), std::vector<glm::vec3>(n), std::vector<std::uint32_t>(n)};
    for (std::uint32_t tri = 0; tri < n; ++tri) {
        for (int k = 0; k < 3; ++k)
            in.boxes[tri].grow(mesh.positions[mesh.indices[3 * std::size_t(tri) + k]]);
        in.centroids[tri] = 0.5f * (in.boxes[tri].lo + in.boxes[tri].hi);
        in.order[tri] = tri;
    }
    return in;
}

// Moves the triangles of bins [0, split.bin] to the front of the range and
// returns where the rest begins. The bin of a triangle is recomputed exactly
// as bestSahSplit() computed it.
std::uint32_t partitionAtSahSplit(BuildInput &in, const BuildTask &task, const Box &centroidBounds,
                                  const Split &split)
{
    const int axis = split.axis;
    const double lo = centroidBounds.lo[axis];
    const double scale = kBins / (double(centroidBounds.hi[axis]) - lo);
    return std::uint32_t(
        std::partition(in.order.begin() + task.begin, in.order.begin() + task.end,
                       [&](std::uint32_t tri) {
                           return std::min(int((in.centroids[tri][axis] - lo) * scale), kBins - 1)
                               <= split.bin;
                       })
        - in.order.begin());
}

// No usable SAH split (identical centroids, or too deep): halve the range
// along the widest centroid axis.
std::uint32_t partitionAtMedian(BuildInput &in, const BuildTask &task, const Box &centroidBounds)
{
    const std::uint32_t count = task.end - task.begin;
    const glm::vec3 extent = centroidBounds.hi - centroidBounds.lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t middle = task.begin + count / 2;
    std::nth_element(in.order.begin() + task.begin, in.order.begin() + middle,
                     in.order.begin() + task.end, [&](std::uint32_t a, std::uint32_t b) {
                         return in.centroids[a][axis] < in.centroids[b][axis];
                     });
    return middle;
}

// Where to split the range of `task` (more than two triangles), after
// reordering it so; std::nullopt when it stays a leaf.
std::optional<std::uint32_t> splitRange(BuildInput &in, const BuildTask &task, const Box &bounds,
                                        const Box &centroidBounds)
{
    const std::uint32_t count = task.end - task.begin;
    std::uint32_t middle = task.begin;
    const Split split = task.depth < kSahDepth
        ? bestSahSplit(in.order, task.begin, task.end, in.boxes, in.centroids, centroidBounds,
                       bounds.halfArea())
        : Split{};
    if (split.axis >= 0 && (split.cost < double(count) || count > kMaxLeafSize))
        middle = partitionAtSahSplit(in, task, centroidBounds, split);
    else if (count > kMaxLeafSize)
        middle = partitionAtMedian(in, task, centroidBounds);
    else
        return std::nullopt; // a leaf: no split pays for its extra traversal
    if (middle == task.begin || middle == task.end)
        middle = task.begin + count / 2; // never an empty child (float bins can round so)
    return middle;
}

// --- Query -------------------------------------------------------------------

// The slab distances round; widening them by a relative 1e-12 (far more
// than the few ulps of error) keeps a box from being missed by a ray
// that hits a triangle inside it, in particular on exact ties in t.
constexpr double kSlack = 1e-12;

// The per-ray part of the slab test per node. An axis the ray runs parallel
// to bounds nothing but must contain the origin (dividing by zero there
// would give NaN for an origin on the slab's plane).
struct RaySlabs {
    glm::dvec3 origin{0.0};
    std::array<bool, 3> parallel{};
    glm::dvec3 inverse{0.0};
    double tMin = 0.0;

    RaySlabs(const Ray &ray, double tMin_)
        : origin(ray.origin)
        , tMin(tMin_)
    {
        for (int a = 0; a < 3; ++a) {
            parallel[a] = ray.direction[a] == 0.0;
            inverse[a] = parallel[a] ? 0.0 : 1.0 / ray.direction[a];
        }
    }

    // The t at which the ray enters the node's box, or infinity when it
    // misses the box within [tMin, limit].
    double enter(const MeshBvh::Node &node, double limit) const
    {
        double tNear = tMin, tFar = limit;
        for (int a = 0; a < 3; ++a) {
            const double lo = node.boundsMin[a], hi = node.boundsMax[a];
            if (parallel[a]) {
                if (origin[a] < lo || origin[a] > hi)
                    return std::numeric_limits<double>::infinity();
                continue;
            }
            double t0 = (lo - origin[a]) * inverse[a], t1 = (hi - origin[a]) * inverse[a];
            if (t0 > t1)
                std::swap(t0, t1);
            tNear = std::max(tNear, t0 - kSlack * std::abs(t0));
            tFar = std::min(tFar, t1 + kSlack * std::abs(t1));
        }
        return tNear <= tFar ? tNear : std::numeric_limits<double>::infinity();
    }
};

// The farthest a box may begin and still hold a hit that could win.
double boxLimit(const std::optional<TriangleHit> &best, double tMax)
{
    return best ? best->t + kSlack * std::abs(best->t) : tMax;
}

// Tests `count` triangles of BVH order (3 vertices and 1 id each) and keeps
// the winner in `best`.
void intersectLeaf(const ShearedRay &sheared, const glm::vec3 *vertices, const std::uint32_t *ids,
                   std::uint32_t count, double tMin, double tMax, std::optional<TriangleHit> &best)
{
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::vec3 *v = &vertices[3 * std::size_t(i)];
        std::optional<TriangleHit> hit =
            intersectSheared(sheared, glm::dvec3(v[0]), glm::dvec3(v[1]), glm::dvec3(v[2]), tMin,
                             best ? best->t : tMax);
        if (!hit)
            continue;
        hit->triangle = ids[i];
        if (better(*hit, best))
            best = hit;
    }
}

} // namespace

std::optional<TriangleHit> closestHitBruteForce(const MeshData &mesh, const Ray &ray, double tMin,
                                                double tMax)
{
    const ShearedRay sheared(ray);
    std::optional<TriangleHit> best;
    for (std::size_t tri = 0; tri < mesh.triangleCount(); ++tri) {
        const glm::dvec3 v0(mesh.positions[mesh.indices[3 * tri]]);
        const glm::dvec3 v1(mesh.positions[mesh.indices[3 * tri + 1]]);
        const glm::dvec3 v2(mesh.positions[mesh.indices[3 * tri + 2]]);
        std::optional<TriangleHit> hit =
            intersectSheared(sheared, v0, v1, v2, tMin, best ? best->t : tMax);
        if (!hit)
            continue;
        hit->triangle = std::uint32_t(tri);
        if (better(*hit, best))
            best = hit;
    }
    return best;
}

MeshBvh::MeshBvh(const MeshData &mesh)
{
    build(mesh);
}

void MeshBvh::build(const MeshData &mesh)
{
    const std::uint32_t n = std::uint32_t(mesh.triangleCount());
    BuildInput in = triangleBounds(mesh, n);

    m_nodes.reserve(n > 0 ? 2 * std::size_t(n) : 1);
    m_nodes.emplace_back();
    std::vector<BuildTask> tasks{BuildTask{0, 0, n, 0}};
    while (!tasks.empty()) {
        const BuildTask task = tasks.back();
        tasks.pop_back();
        m_depth = std::max(m_depth, task.depth);
        Box bounds, centroidBounds;
        for (std::uint32_t i = task.begin; i < task.end; ++i) {
            bounds.grow(in.boxes[in.order[i]]);
            centroidBounds.grow(in.centroids[in.order[i]]);
        }
        Node &node = m_nodes[task.node];
        node.boundsMin = bounds.empty() ? glm::vec3(0.0f) : bounds.lo;
        node.boundsMax = bounds.empty() ? glm::vec3(0.0f) : bounds.hi;
        node.first = task.begin;
        node.count = task.end - task.begin;
        const std::uint32_t count = task.end - task.begin;
        if (count <= 2)
            continue; // a leaf: splitting two triangles saves nothing

        const std::optional<std::uint32_t> middle = splitRange(in, task, bounds, centroidBounds);
        if (!middle)
            continue;
        const std::uint32_t left = std::uint32_t(m_nodes.size());
        m_nodes[task.node].first = left; // `node` may dangle after emplace_back
        m_nodes[task.node].count = 0;
        m_nodes.emplace_back();
        m_nodes.emplace_back();
        tasks.push_back(BuildTask{left + 1, *middle, task.end, task.depth + 1});
        tasks.push_back(BuildTask{left, task.begin, *middle, task.depth + 1});
    }
    Q_ASSERT(m_depth <= kMaxDepth);

    m_vertices.resize(3 * std::size_t(n));
    for (std::uint32_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k)
            m_vertices[3 * std::size_t(i) + k] =
                mesh.positions[mesh.indices[3 * std::size_t(in.order[i]) + k]];
    m_triangleIds = std::move(in.order);
}

std::optional<TriangleHit> MeshBvh::closestHit(const Ray &ray, double tMin, double tMax) const
{
    if (m_triangleIds.empty() || !(tMin <= tMax))
        return std::nullopt;
    const ShearedRay sheared(ray);
    if (!sheared.valid)
        return std::nullopt;
    const RaySlabs slabs(ray, tMin);

    std::optional<TriangleHit> best;
    if (slabs.enter(m_nodes[0], tMax) == std::numeric_limits<double>::infinity())
        return std::nullopt;
    std::array<std::uint32_t, kMaxDepth + 2> stack{};
    int top = 0;
    std::uint32_t current = 0;
    for (;;) {
        const Node &node = m_nodes[current];
        if (node.count > 0) {
            intersectLeaf(sheared, &m_vertices[3 * std::size_t(node.first)],
                          &m_triangleIds[node.first], node.count, tMin, tMax, best);
        } else {
            // Nearer child first: its hits shrink the limit the other is tested with.
            const double l = boxLimit(best, tMax);
            double tLeft = slabs.enter(m_nodes[node.first], l),
                   tRight = slabs.enter(m_nodes[node.first + 1], l);
            std::uint32_t nearChild = node.first, farChild = node.first + 1;
            if (tRight < tLeft) {
                std::swap(tLeft, tRight);
                std::swap(nearChild, farChild);
            }
            if (tLeft != std::numeric_limits<double>::infinity()) {
                if (tRight != std::numeric_limits<double>::infinity())
                    stack[top++] = farChild;
                current = nearChild;
                continue;
            }
        }
        // Next node from the stack, skipping those a hit found since has ruled out.
        bool found = false;
        while (top > 0) {
            const std::uint32_t candidate = stack[--top];
            if (slabs.enter(m_nodes[candidate], boxLimit(best, tMax))
                != std::numeric_limits<double>::infinity()) {
                current = candidate;
                found = true;
                break;
            }
        }
        if (!found)
            break;
    }
    return best;
}

} // namespace phonglab
