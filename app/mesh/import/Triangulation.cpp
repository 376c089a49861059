#include "Triangulation.h"

#include <cmath>

namespace phonglab {

namespace {

struct Point2 {
    double x = 0.0, y = 0.0;
    bool operator==(const Point2 &) const = default;
};

// Twice the signed area of (o, a, b): positive when counter-clockwise.
double orient(const Point2 &o, const Point2 &a, const Point2 &b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Whether the outline turns left at b, by more than rounding: a corner
// that sits on the line through its neighbours (to within a sine of 1e-6,
// float positions being no more exact) counts as no turn, so it is never
// cut off as a flat sliver and it still blocks ears that would cover it.
bool turnsLeft(const Point2 &a, const Point2 &b, const Point2 &c)
{
    const double abx = b.x - a.x, aby = b.y - a.y, bcx = c.x - b.x, bcy = c.y - b.y;
    return orient(a, b, c) > 1e-6 * std::sqrt((abx * abx + aby * aby) * (bcx * bcx + bcy * bcy));
}

// Whether p lies left of the line a → b or on it, to the same tolerance.
bool leftOrOn(const Point2 &a, const Point2 &b, const Point2 &p)
{
    const double abx = b.x - a.x, aby = b.y - a.y, apx = p.x - a.x, apy = p.y - a.y;
    return orient(a, b, p) >= -1e-6 * std::sqrt((abx * abx + aby * aby) * (apx * apx + apy * apy));
}

// Which half of the circle an edge direction points into: [0, π) or [π, 2π).
int half(const Point2 &from, const Point2 &to)
{
    const double dx = to.x - from.x, dy = to.y - from.y;
    return (dy < 0.0 || (dy == 0.0 && dx < 0.0)) ? 1 : 0;
}

// Splits one polygon. Keeps its scratch buffers between polygons so a mesh
// of quads and n-gons costs no allocation per face.
class PolygonTriangulator
{
public:
    // Appends the triangles of corners [first, first + n) to `out`; false
    // when ear clipping failed and (part of) the polygon was fanned.
    bool run(std::span<const glm::vec3> positions, const std::uint32_t *cornerPosition,
             std::uint32_t first, std::uint32_t n, std::vector<std::uint32_t> &out);

private:
    bool project(std::span<const glm::vec3> positions, const std::uint32_t *polygon,
                 std::uint32_t n);
    bool isConvex() const;
    bool isReflex(std::uint32_t i) const
    {
        return !turnsLeft(m_points[m_prev[i]], m_points[i], m_points[m_next[i]]);
    }
    bool isEar(std::uint32_t i) const;
    void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c)
    {
        m_out->insert(m_out->end(), {m_first + a, m_first + b, m_first + c});
    }
    void fanFrom(std::uint32_t start);
    bool clipEars(std::uint32_t n);

    std::vector<Point2> m_points;
    std::vector<std::uint32_t> m_prev, m_next;
    std::vector<char> m_reflex;
    std::vector<std::uint32_t> *m_out = nullptr;
    std::uint32_t m_first = 0;
};

// Coordinates in the plane perpendicular to the Newell normal, with axes
// chosen so the polygon winds counter-clockwise there. False when the
// polygon has no area to speak of (its normal is undefined).
bool PolygonTriangulator::project(std::span<const glm::vec3> positions,
                                  const std::uint32_t *polygon, std::uint32_t n)
{
    const glm::dvec3 normal = newellNormal(positions, std::span(polygon, n));
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length))
        return false;
    const glm::dvec3 w = normal / length;
    // Cross with the axis least aligned with w: never (nearly) parallel.
    const glm::dvec3 a = std::abs(w.x) < std::abs(w.y)
        ? (std::abs(w.x) < std::abs(w.z) ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1))
        : (std::abs(w.y) < std::abs(w.z) ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1));
    const glm::dvec3 u = glm::normalize(glm::cross(w, a));
    const glm::dvec3 v = glm::cross(w, u); // u × v = w: counter-clockwise about the normal
    // Relative to the first corner, so large coordinates lose no precision.
    const glm::dvec3 origin(positions[polygon[0]]);
    m_points.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::dvec3 d = glm::dvec3(positions[polygon[i]]) - origin;
        m_points[i] = {glm::dot(d, u), glm::dot(d, v)};
    }
    return true;
}

// Strictly convex and turning around exactly once. Every corner turning left
// is not enough: a pentagram does that too, but its edges sweep the circle
// twice, so the edge direction wraps from the lower half to the upper twice.
bool PolygonTriangulator::isConvex() const
{
    const auto n = std::uint32_t(m_points.size());
    int wraps = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const Point2 &a = m_points[i];
        const Point2 &b = m_points[(i + 1) % n];
        const Point2 &c = m_points[(i + 2) % n];
        if (!turnsLeft(a, b, c))
            return false;
        if (half(a, b) == 1 && half(b, c) == 0)
            ++wraps;
    }
    return wraps == 1;
}

// Corner i of the remaining polygon is an ear when it turns left and no
// reflex corner lies in or on the triangle it would cut off. (Convex corners
// cannot lie inside an ear of a simple polygon.) Corners at the same spot as
// the triangle's own, as polygons with bridged holes have, do not block.
bool PolygonTriangulator::isEar(std::uint32_t i) const
{
    const std::uint32_t prev = m_prev[i], next = m_next[i];
    const Point2 &a = m_points[prev], &b = m_points[i], &c = m_points[next];
    if (!turnsLeft(a, b, c))
        return false;
    for (std::uint32_t j = m_next[next]; j != prev; j = m_next[j]) {
        if (!m_reflex[j])
            continue;
        const Point2 &p = m_points[j];
        if (p == a || p == b || p == c)
            continue;
        if (leftOrOn(a, b, p) && leftOrOn(b, c, p) && leftOrOn(c, a, p))
            return false;
    }
    return true;
}

void PolygonTriangulator::fanFrom(std::uint32_t start)
{
    for (std::uint32_t b = m_next[start]; m_next[b] != start; b = m_next[b])
        addTriangle(start, b, m_next[b]);
}

bool PolygonTriangulator::run(std::span<const glm::vec3> positions,
                              const std::uint32_t *cornerPosition, std::uint32_t first,
                              std::uint32_t n, std::vector<std::uint32_t> &out)
{
    m_out = &out;
    m_first = first;
    m_prev.resize(n);
    m_next.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        m_prev[i] = (i + n - 1) % n;
        m_next[i] = (i + 1) % n;
    }
    if (!project(positions, cornerPosition + first, n)) {
        fanFrom(0);
        return false;
    }
    if (isConvex()) {
        fanFrom(0);
        return true;
    }
    return clipEars(n);
}

// Ear clipping of the projected polygon of n corners; false when it had to
// give up and fan the rest.
bool PolygonTriangulator::clipEars(std::uint32_t n)
{
    m_reflex.resize(n);
    int reflexCount = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        m_reflex[i] = isReflex(i);
        reflexCount += m_reflex[i];
    }

    std::uint32_t remaining = n;
    std::uint32_t i = 0;
    std::uint32_t sinceLastEar = 0;
    while (remaining > 3) {
        if (reflexCount == 0) {
            // What is left is convex: nothing can block an ear any more.
            fanFrom(i);
            return true;
        }
        if (!isEar(i)) {
            i = m_next[i];
            // A whole lap without an ear: the outline crosses itself or
            // folds onto itself. Fan the rest rather than loop forever.
            if (++sinceLastEar > remaining) {
                fanFrom(i);
                return false;
            }
            continue;
        }
        const std::uint32_t prev = m_prev[i], next = m_next[i];
        addTriangle(prev, i, next);
        m_next[prev] = next;
        m_prev[next] = prev;
        --remaining;
        sinceLastEar = 0;
        // Only the two neighbours' turns change when an ear goes.
        for (std::uint32_t k : {prev, next}) {
            const bool reflex = isReflex(k);
            reflexCount += int(reflex) - int(m_reflex[k]);
            m_reflex[k] = reflex;
        }
        // Continue from the previous corner: its turn just changed, so it
        // is the likeliest new ear.
        i = prev;
    }
    addTriangle(m_prev[i], i, m_next[i]);
    return true;
}

// Quads, the commonest polygon, need no projection: split along the
// diagonal a–c when both halves face the way the quad does (neither b nor
// d is reflex), else along b–d. A quad's Newell normal is (c − a) × (d − b).
bool splitQuad(std::span<const glm::vec3> positions, const std::uint32_t *cornerPosition,
               std::uint32_t first, std::vector<std::uint32_t> &out)
{
    const glm::dvec3 a(positions[cornerPosition[first]]), b(positions[cornerPosition[first + 1]]),
        c(positions[cornerPosition[first + 2]]), d(positions[cornerPosition[first + 3]]);
    const glm::dvec3 normal = glm::cross(c - a, d - b);
    const auto facesAlong = [&](const glm::dvec3 &p, const glm::dvec3 &q, const glm::dvec3 &r) {
        return glm::dot(glm::cross(q - p, r - p), normal) > 0.0;
    };
    if (!facesAlong(a, b, c) || !facesAlong(a, c, d)) {
        if (facesAlong(b, c, d) && facesAlong(b, d, a)) {
            out.insert(out.end(), {first + 1, first + 2, first + 3, first + 1, first + 3, first});
            return true;
        }
        // Neither diagonal works: the quad crosses itself or has no area.
        out.insert(out.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
        return false;
    }
    out.insert(out.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    return true;
}

} // namespace

glm::dvec3 newellNormal(std::span<const glm::vec3> positions,
                        std::span<const std::uint32_t> polygon)
{
    // Sum of the fan's cross products about the first corner: the same as
    // Newell's formula, with smaller numbers and so less rounding.
    glm::dvec3 normal(0.0);
    if (polygon.size() < 3)
        return normal;
    const glm::dvec3 origin(positions[polygon[0]]);
    glm::dvec3 previous = glm::dvec3(positions[polygon[1]]) - origin;
    for (std::size_t i = 2; i < polygon.size(); ++i) {
        const glm::dvec3 current = glm::dvec3(positions[polygon[i]]) - origin;
        normal += glm::cross(previous, current);
        previous = current;
    }
    return normal;
}

Triangulation triangulate(const PolygonMesh &mesh)
{
    Triangulation result;
    const std::size_t faces = mesh.faceCount();
    std::size_t triangleCorners = 0;
    for (std::size_t f = 0; f < faces; ++f)
        triangleCorners += mesh.cornerCount(f) >= 3 ? 3 * (mesh.cornerCount(f) - 2) : 0;
    result.corners.reserve(triangleCorners);

    PolygonTriangulator triangulator;
    for (std::size_t f = 0; f < faces; ++f) {
        const std::uint32_t first = mesh.faceStart[f];
        const std::uint32_t n = mesh.faceStart[f + 1] - first;
        if (n < 3)
            continue; // repair drops these; nothing to draw if one slips through
        if (n == 3) {
            result.corners.insert(result.corners.end(), {first, first + 1, first + 2});
            continue;
        }
        const bool ok = n == 4
            ? splitQuad(mesh.positions, mesh.cornerPosition.data(), first, result.corners)
            : triangulator.run(mesh.positions, mesh.cornerPosition.data(), first, n,
                               result.corners);
        result.fanFallbacks += !ok;
    }
    return result;
}

} // namespace phonglab
