#include "core/reference/AnalyticRaycaster.h"

#include "core/reference/PhongReference.h"
#include "core/scene/AnalyticShapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace phonglab {

namespace {

// --- Polynomial roots --------------------------------------------------------
//
// The torus needs the real roots of a quartic. Closed-form quartic solutions
// lose most of their digits exactly where it matters (grazing rays, rays along
// the axis), so instead the roots are isolated: between two consecutive
// roots of the derivative a polynomial is monotonic, so a sign change there
// brackets exactly one root, and bisection converges on it unconditionally.
// The derivative's roots come from the same procedure one degree down.

constexpr int kMaxDegree = 4;
using Coefficients = std::array<double, kMaxDegree + 1>; // c[0] + c[1]·t + ... + c[4]·t⁴

double evaluate(const Coefficients &c, int degree, double t)
{
    double value = c[degree];
    for (int i = degree - 1; i >= 0; --i)
        value = value * t + c[i];
    return value;
}

// Bisection on [lo, hi] where the polynomial changes sign. Stops at ~1e-13
// absolute (the callers work in units of the object's size) or when the
// interval can no longer be split in double.
double bisect(const Coefficients &c, int degree, double lo, double hi, double valueLo)
{
    constexpr double kTolerance = 1e-13;
    for (int i = 0; i < 200 && hi - lo > kTolerance; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi)
            break;
        const double value = evaluate(c, degree, mid);
        if (value == 0.0)
            return mid;
        if ((value < 0.0) == (valueLo < 0.0)) {
            lo = mid;
            valueLo = value;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

// Real roots in [lo, hi], ascending; returns how many were written to roots.
// Roots of even multiplicity (tangent rays) are found only when the
// polynomial is exactly zero there: they sit on the silhouette, where a
// tessellated mesh and the analytic surface disagree anyway.
int rootsInInterval(const Coefficients &c, int degree, double lo, double hi, double *roots)
{
    while (degree > 0 && c[degree] == 0.0)
        --degree; // leading zeros: the polynomial is really of lower degree
    if (degree == 0)
        return 0;
    if (degree == 1) {
        const double t = -c[0] / c[1];
        if (t < lo || t > hi)
            return 0;
        roots[0] = t;
        return 1;
    }

    Coefficients derivative{};
    for (int i = 1; i <= degree; ++i)
        derivative[i - 1] = i * c[i];
    std::array<double, kMaxDegree + 1> bounds{};
    bounds[0] = lo;
    const int criticalCount = rootsInInterval(derivative, degree - 1, lo, hi, bounds.data() + 1);
    bounds[criticalCount + 1] = hi;

    int count = 0;
    double a = bounds[0];
    double valueA = evaluate(c, degree, a);
    for (int i = 1; i <= criticalCount + 1; ++i) {
        const double b = bounds[i];
        const double valueB = evaluate(c, degree, b);
        if (valueA == 0.0 && (count == 0 || roots[count - 1] != a))
            roots[count++] = a;
        else if ((valueA < 0.0) != (valueB < 0.0) && valueB != 0.0)
            roots[count++] = bisect(c, degree, a, b, valueA);
        a = b;
        valueA = valueB;
    }
    if (valueA == 0.0 && (count == 0 || roots[count - 1] != a))
        roots[count++] = a;
    return count;
}

} // namespace

Ray cameraRay(const Camera &camera, int x, int y, int width, int height)
{
    const double aspect = double(width) / double(height);
    const double tanHalfFov = std::tan(glm::radians(camera.fovDeg) * 0.5);
    // Pixel centres, the points OpenGL samples when rasterising.
    const double ndcX = 2.0 * (x + 0.5) / width - 1.0;
    const double ndcY = 1.0 - 2.0 * (y + 0.5) / height; // row 0 is the top
    return Ray{glm::dvec3(0.0), glm::dvec3(ndcX * tanHalfFov * aspect, ndcY * tanHalfFov, -1.0)};
}

std::optional<double> intersectUnitSphere(const Ray &ray, double tMin, double tMax)
{
    // Solved about the point of the ray closest to the centre rather than
    // with the textbook discriminant, which cancels badly when the sphere is
    // small compared with its distance (Haines et al., Ray Tracing Gems ch. 7).
    const double length = glm::length(ray.direction);
    if (length == 0.0)
        return std::nullopt;
    const glm::dvec3 d = ray.direction / length;
    const double tClosest = -glm::dot(ray.origin, d);
    const glm::dvec3 closest = ray.origin + tClosest * d;
    const double halfChord2 = 1.0 - glm::dot(closest, closest);
    if (halfChord2 < 0.0)
        return std::nullopt;
    const double halfChord = std::sqrt(halfChord2);
    for (const double u : {tClosest - halfChord, tClosest + halfChord}) {
        const double t = u / length;
        if (t >= tMin && t <= tMax)
            return t;
    }
    return std::nullopt;
}

std::optional<double> intersectTorus(const Ray &ray, double tMin, double tMax, double majorRadius,
                                     double minorRadius)
{
    const double length = glm::length(ray.direction);
    if (length == 0.0 || !(tMin <= tMax))
        return std::nullopt;
    const glm::dvec3 d = ray.direction / length; // u = t·length along a unit direction

    // Clip the ray to the bounding sphere first: it skips most rays cheaply,
    // and moving the origin to the entry point keeps the quartic's
    // coefficients of order one however far away the camera is.
    const double bound = (majorRadius + minorRadius) * (1.0 + 1e-9);
    const double uClosest = -glm::dot(ray.origin, d);
    const glm::dvec3 closest = ray.origin + uClosest * d;
    const double halfChord2 = bound * bound - glm::dot(closest, closest);
    if (halfChord2 < 0.0)
        return std::nullopt;
    const double halfChord = std::sqrt(halfChord2);
    const double uLo = std::max(uClosest - halfChord, tMin * length);
    const double uHi = std::min(uClosest + halfChord, tMax * length);
    if (uLo > uHi)
        return std::nullopt;

    // f(p) = (|p|² + R² - r²)² - 4R²(x² + z²), negative inside the tube,
    // along p = o + s·d with |d| = 1:
    //   |p|² + R² - r² = s² + 2a·s + b,   a = o·d,  b = |o|² + R² - r²
    //   x² + z²        = e·s² + 2g·s + h, e = dx² + dz², g = ox·dx + oz·dz, h = ox² + oz²
    const glm::dvec3 o = ray.origin + uLo * d;
    const double R2 = majorRadius * majorRadius;
    const double a = glm::dot(o, d);
    const double b = glm::dot(o, o) + R2 - minorRadius * minorRadius;
    const double e = d.x * d.x + d.z * d.z;
    const double g = o.x * d.x + o.z * d.z;
    const double h = o.x * o.x + o.z * o.z;
    const Coefficients c{b * b - 4.0 * R2 * h, 4.0 * a * b - 8.0 * R2 * g,
                         4.0 * a * a + 2.0 * b - 4.0 * R2 * e, 4.0 * a, 1.0};
    std::array<double, kMaxDegree> roots{};
    if (rootsInInterval(c, kMaxDegree, 0.0, uHi - uLo, roots.data()) == 0)
        return std::nullopt;
    return (uLo + roots[0]) / length;
}

std::optional<double> intersectUnitBox(const Ray &ray, double tMin, double tMax)
{
    // Slabs: the ray is inside the box where it is inside all three.
    double enter = -std::numeric_limits<double>::infinity();
    double leave = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis], d = ray.direction[axis];
        if (d == 0.0) {
            if (o < -1.0 || o > 1.0)
                return std::nullopt;
            continue;
        }
        double t0 = (-1.0 - o) / d, t1 = (1.0 - o) / d;
        if (t0 > t1)
            std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
    }
    if (enter > leave)
        return std::nullopt;
    if (enter >= tMin && enter <= tMax)
        return enter;
    if (leave >= tMin && leave <= tMax) // the near plane cuts the box
        return leave;
    return std::nullopt;
}

glm::dvec3 boxNormal(const glm::dvec3 &p)
{
    const glm::dvec3 a = glm::abs(p);
    if (a.x >= a.y && a.x >= a.z)
        return {p.x > 0 ? 1.0 : -1.0, 0.0, 0.0};
    if (a.y >= a.z)
        return {0.0, p.y > 0 ? 1.0 : -1.0, 0.0};
    return {0.0, 0.0, p.z > 0 ? 1.0 : -1.0};
}

glm::dvec3 torusNormal(const glm::dvec3 &p, double majorRadius)
{
    // From p, away from the nearest point of the tube's centre circle.
    const glm::dvec3 ringPoint = majorRadius * glm::normalize(glm::dvec3(p.x, 0.0, p.z));
    return glm::normalize(p - ringPoint);
}

ReferenceShading idealShadingFor(ShadingMethod method)
{
    switch (method) {
    case ShadingMethod::BlinnPhong: return ReferenceShading::BlinnPhong;
    case ShadingMethod::Normals: return ReferenceShading::Normals;
    case ShadingMethod::Phong:
    case ShadingMethod::Gouraud:
    case ShadingMethod::Flat:
    case ShadingMethod::Faceted: break;
    }
    return ReferenceShading::Phong;
}

} // namespace phonglab
