#include "core/reference/AnalyticRaycaster.h"

#include "core/view/ObjectMatrices.h"
#include "core/reference/AnalyticShapes.h"
#include "core/reference/PhongReference.h"
#include "core/reference/ReferenceSample.h"

#include <QCoreApplication>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct AnalyticRaycasterWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::AnalyticRaycaster)
};

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

// --- Scene preparation -------------------------------------------------------

using Surface = AnalyticShape;

// Everything one object needs per ray, computed once per image.
struct PreparedObject {
    Surface surface = Surface::Sphere;
    glm::dmat4 modelView{1.0};
    glm::dmat3 normalMatrix{1.0};
    glm::dmat4 model{1.0};
    glm::dmat3 inverseLinear{1.0}; // camera-space directions -> object space
    glm::dvec3 eyeInObject{0.0};   // the camera-space origin in object space
    const Material *material = nullptr;
};

std::optional<Surface> analyticSurfaceFor(const QString &meshAsWritten,
                                          const QHash<QString, QString> &standIns)
{
    return analyticShapeFor(standIns.value(meshAsWritten, meshAsWritten));
}

Result<std::vector<PreparedObject>> prepareObjects(const Scene &scene, double aspect,
                                                   const QHash<QString, QString> &standIns)
{
    const glm::dmat4 view = scene.camera.viewMatrix();
    const glm::dmat4 projection = scene.camera.projectionMatrix(aspect);
    std::vector<PreparedObject> prepared;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject &object = scene.objects[i];
        const std::optional<Surface> surface = analyticSurfaceFor(object.mesh, standIns);
        if (!surface)
            return fail(
                AnalyticRaycasterWords::tr("Object %1: mesh \"%2\" has no analytic surface "
                                           "(the reference ray caster knows builtin:sphere, "
                                           "builtin:torus and builtin:cube)")
                    .arg(i)
                    .arg(object.mesh));
        const ObjectMatrices matrices =
            ObjectMatrices::make(object.transform.matrix(), view, projection);
        // A zero scale flattens the object to something with no defined
        // normals; there is no meaningful reference for it, so it is left out.
        const double det = glm::determinant(glm::dmat3(matrices.modelView));
        if (!std::isfinite(det) || std::abs(det) < 1e-300)
            continue;
        const glm::dmat4 inverse = glm::inverse(matrices.modelView);
        PreparedObject p;
        p.surface = *surface;
        p.modelView = matrices.modelView;
        p.normalMatrix = matrices.normalMatrix;
        p.model = matrices.model;
        p.inverseLinear = glm::dmat3(inverse);
        p.eyeInObject = glm::dvec3(inverse * glm::dvec4(0.0, 0.0, 0.0, 1.0));
        p.material = &object.material;
        prepared.push_back(p);
    }
    return prepared;
}

struct Hit {
    double t = std::numeric_limits<double>::infinity();
    const PreparedObject *object = nullptr;
    glm::dvec3 objectPoint{0.0};
};

// The nearest surface along a camera ray over all objects. Each object is
// intersected in its own space with the ray mapped through inverse(modelView);
// a linear map keeps the parameter t, so t stays the camera-space depth.
Hit nearestHit(const std::vector<PreparedObject> &objects, const glm::dvec3 &cameraDirection,
               double nearPlane, double farPlane)
{
    Hit best;
    for (const PreparedObject &object : objects) {
        const Ray ray{object.eyeInObject, object.inverseLinear * cameraDirection};
        const double tMax = std::min(farPlane, best.t);
        std::optional<double> t;
        switch (object.surface) {
        case Surface::Sphere: t = intersectUnitSphere(ray, nearPlane, tMax); break;
        case Surface::Torus:
            t = intersectTorus(ray, nearPlane, tMax, kTorusMajorRadius, kTorusMinorRadius);
            break;
        case Surface::Box: t = intersectUnitBox(ray, nearPlane, tMax); break;
        }
        // Strictly nearer only: on an exact tie the GPU's GL_LESS depth test
        // keeps the object drawn first.
        if (t && *t < best.t) {
            best.t = *t;
            best.object = &object;
            best.objectPoint = ray.at(*t);
        }
    }
    return best;
}

ReferenceSample shade(const Hit &hit, const Scene &scene, std::span<const CameraSpaceLight> lights,
                      const ReferenceShader &shader)
{
    const PreparedObject &object = *hit.object;
    const glm::dvec3 p = hit.objectPoint;
    // Exact normals of the analytic surface, mapped like the GPU maps vertex
    // normals. No flip towards the viewer: phong.frag does not flip either,
    // so an inside seen through the near plane is lit as the GPU lights it.
    const glm::dvec3 objectNormal = object.surface == Surface::Sphere ? p
        : object.surface == Surface::Torus ? torusNormal(p, kTorusMajorRadius)
                                           : boxNormal(p);
    return shadeReferenceHit({p, objectNormal, object.modelView, object.normalMatrix, object.model},
                             *object.material, scene.ambient, lights, shader);
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

Result<ReferenceImage> raycastScene(const Scene &scene, int width, int height,
                                    const QHash<QString, QString> &standIns)
{
    return raycastScene(scene, width, height, ReferenceShading::Phong, standIns);
}

Result<ReferenceImage> raycastScene(const Scene &scene, int width, int height,
                                    const ReferenceShader &shader,
                                    const QHash<QString, QString> &standIns)
{
    if (width <= 0 || height <= 0)
        return fail(AnalyticRaycasterWords::tr("Invalid reference image size %1x%2")
                        .arg(width)
                        .arg(height));
    const Result<std::vector<PreparedObject>> objects =
        prepareObjects(scene, double(width) / double(height), standIns);
    if (!objects)
        return fail(objects.error());

    const std::vector<CameraSpaceLight> lights = enabledCameraSpaceLights(scene, shader);

    ReferenceImage image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const Ray ray = cameraRay(scene.camera, x, y, width, height);
            const Hit hit =
                nearestHit(*objects, ray.direction, scene.camera.nearPlane, scene.camera.farPlane);
            if (!hit.object)
                continue;
            const std::size_t i = image.index(x, y);
            image.coverage[i] = 1;
            image.depth[i] = hit.t;
            const ReferenceSample sample = shade(hit, scene, lights, shader);
            image.color[i] = sample.color;
            image.specular[i] = sample.specular;
        }
    }
    return image;
}

} // namespace phonglab
