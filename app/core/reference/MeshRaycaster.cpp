#include "core/reference/MeshRaycaster.h"

#include "core/reference/MeshBvh.h"
#include "core/reference/ReferenceSample.h"
#include "core/reference/SceneHits.h"
#include "core/scene/AnalyticShapes.h"
#include "core/support/ParallelRows.h"
#include "core/view/ObjectMatrices.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct MeshRaycasterWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::MeshRaycaster)
};

namespace {

enum class Surface {
    Mesh,
    Sphere,
    Torus,
    Box
};

// Everything one object needs per ray, computed once per image.
struct PreparedObject {
    Surface surface = Surface::Mesh;
    int index = 0;                      // in Scene::objects
    const MeshData *mesh = nullptr;     // Surface::Mesh: its vertex normals
    std::shared_ptr<const MeshBvh> bvh; // Surface::Mesh: its triangles
    glm::dmat4 modelView{1.0};
    glm::dmat3 normalMatrix{1.0};
    glm::dmat4 model{1.0};
    glm::dmat3 inverseLinear{1.0}; // camera-space directions -> object space
    glm::dvec3 eyeInObject{0.0};   // the camera-space origin in object space
    const Material *material = nullptr;
};

// A builtin's analytic surface (the mesh ray-caster has one more kind: Mesh).
std::optional<Surface> builtinSurface(const QString &spec)
{
    const std::optional<AnalyticShape> shape = analyticShapeFor(spec);
    if (!shape)
        return std::nullopt;
    switch (*shape) {
    case AnalyticShape::Sphere: return Surface::Sphere;
    case AnalyticShape::Torus: return Surface::Torus;
    case AnalyticShape::Box: return Surface::Box;
    }
    return std::nullopt;
}

// The BVH of each distinct mesh (null until built) and the triangles all of
// them hold, the measure of the build's progress.
struct MeshBvhs {
    std::unordered_map<const MeshData *, std::shared_ptr<const MeshBvh>> byMesh;
    std::size_t trianglesToBuild = 0;
};

// A failure on a size mismatch, or an object with neither a valid mesh nor
// an analytic surface; otherwise every distinct mesh is entered in `bvhs`.
Result<> checkObjectMeshes(const Scene &scene,
                           const std::vector<std::shared_ptr<const MeshData>> &objectMeshes,
                           MeshBvhs &bvhs)
{
    if (objectMeshes.size() != scene.objects.size())
        return fail(MeshRaycasterWords::tr("The scene has %1 objects but %2 meshes were given")
                        .arg(scene.objects.size())
                        .arg(objectMeshes.size()));
    for (std::size_t i = 0; i < objectMeshes.size(); ++i) {
        const MeshData *mesh = objectMeshes[i].get();
        if (!mesh) {
            if (!builtinSurface(scene.objects[i].mesh))
                return fail(MeshRaycasterWords::tr(
                                "Object %1: mesh \"%2\" was given no triangle mesh and has no "
                                "analytic surface (builtin:sphere, builtin:torus, builtin:cube)")
                                .arg(i)
                                .arg(scene.objects[i].mesh));
        } else if (!mesh->isValid()) {
            return fail(
                MeshRaycasterWords::tr("Object %1: the triangle mesh for \"%2\" is not valid")
                    .arg(i)
                    .arg(scene.objects[i].mesh));
        } else if (bvhs.byMesh.emplace(mesh, nullptr).second) {
            bvhs.trianglesToBuild += mesh->triangleCount();
        }
    }
    return {};
}

// The per-ray transforms of an object from its matrices.
void setTransforms(PreparedObject &p, const ObjectMatrices &matrices)
{
    const glm::dmat4 inverse = glm::inverse(matrices.modelView);
    p.modelView = matrices.modelView;
    p.normalMatrix = matrices.normalMatrix;
    p.model = matrices.model;
    p.inverseLinear = glm::dmat3(inverse);
    p.eyeInObject = glm::dvec3(inverse * glm::dvec4(0.0, 0.0, 0.0, 1.0));
}

// Checks the inputs, builds one BVH per distinct mesh (reporting the first
// tenth of the progress) and prepares the objects. A failure on bad input,
// or "cancelled".
Result<> prepareObjects(const Scene &scene,
                        const std::vector<std::shared_ptr<const MeshData>> &objectMeshes,
                        double aspect, std::vector<PreparedObject> &prepared,
                        const std::function<bool(double)> &progress)
{
    MeshBvhs bvhs;
    if (Result<> checked = checkObjectMeshes(scene, objectMeshes, bvhs); !checked)
        return checked;

    const glm::dmat4 view = scene.camera.viewMatrix();
    const glm::dmat4 projection = scene.camera.projectionMatrix(aspect);
    std::size_t trianglesBuilt = 0;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject &object = scene.objects[i];
        const ObjectMatrices matrices =
            ObjectMatrices::make(object.transform.matrix(), view, projection);
        // A zero scale flattens the object to something with no defined
        // normals; there is no reference for it.
        const double det = glm::determinant(glm::dmat3(matrices.modelView));
        if (!std::isfinite(det) || std::abs(det) < 1e-300)
            continue;
        PreparedObject p;
        p.index = int(i);
        if (const MeshData *mesh = objectMeshes[i].get()) {
            std::shared_ptr<const MeshBvh> &bvh = bvhs.byMesh[mesh];
            if (!bvh) {
                if (progress
                    && !progress(0.1 * double(trianglesBuilt)
                                 / double(std::max<std::size_t>(bvhs.trianglesToBuild, 1))))
                    return fail(QStringLiteral("cancelled"));
                bvh = std::make_shared<const MeshBvh>(*mesh);
                trianglesBuilt += mesh->triangleCount();
            }
            p.surface = Surface::Mesh;
            p.mesh = mesh;
            p.bvh = bvh;
        } else {
            p.surface = *builtinSurface(object.mesh);
        }
        setTransforms(p, matrices);
        p.material = &object.material;
        prepared.push_back(std::move(p));
    }
    return {};
}

struct Hit {
    double t = std::numeric_limits<double>::infinity();
    const PreparedObject *object = nullptr;
    glm::dvec3 objectPoint{0.0};
    glm::dvec3 objectNormal{0.0}; // not normalised: the normal matrix comes first
    std::int32_t triangle = -1;
    glm::dvec3 barycentric{0.0};
};

// The interpolated vertex normal at a mesh hit, in object space.
glm::dvec3 interpolatedNormal(const MeshData &mesh, const TriangleHit &hit)
{
    const std::size_t base = 3 * std::size_t(hit.triangle);
    return hit.interpolate(glm::dvec3(mesh.normals[mesh.indices[base]]),
                           glm::dvec3(mesh.normals[mesh.indices[base + 1]]),
                           glm::dvec3(mesh.normals[mesh.indices[base + 2]]));
}

// The nearest surface along a camera ray over all objects, each intersected
// in its own space; a linear map keeps t, so t stays the camera depth.
// Without kSurface only t and the object are found: where surfaces are,
// not how they look (SceneDepthCaster), which spares the normal's
// interpolation. Same objects, order and tie rule either way, so the same t.
template <bool kSurface>
Hit nearestHit(const std::vector<PreparedObject> &objects, const glm::dvec3 &cameraDirection,
               double nearPlane, double farPlane)
{
    Hit best;
    for (const PreparedObject &object : objects) {
        const Ray ray{object.eyeInObject, object.inverseLinear * cameraDirection};
        const double tMax = std::min(farPlane, best.t);
        std::optional<double> t;
        std::optional<TriangleHit> triangleHit;
        switch (object.surface) {
        case Surface::Mesh:
            if ((triangleHit = object.bvh->closestHit(ray, nearPlane, tMax)))
                t = triangleHit->t;
            break;
        case Surface::Sphere: t = intersectUnitSphere(ray, nearPlane, tMax); break;
        case Surface::Torus:
            t = intersectTorus(ray, nearPlane, tMax, kTorusMajorRadius, kTorusMinorRadius);
            break;
        case Surface::Box: t = intersectUnitBox(ray, nearPlane, tMax); break;
        }
        // Strictly nearer only: on an exact tie the GPU's GL_LESS depth test
        // keeps the object drawn first.
        if (!t || !(*t < best.t))
            continue;
        best.t = *t;
        best.object = &object;
        if constexpr (kSurface) {
            best.objectPoint = ray.at(*t);
            best.triangle = triangleHit ? std::int32_t(triangleHit->triangle) : -1;
            best.barycentric = triangleHit ? triangleHit->barycentric : glm::dvec3(0.0);
            switch (object.surface) {
            case Surface::Mesh:
                best.objectNormal = interpolatedNormal(*object.mesh, *triangleHit);
                break;
            case Surface::Sphere: best.objectNormal = best.objectPoint; break;
            case Surface::Torus:
                best.objectNormal = torusNormal(best.objectPoint, kTorusMajorRadius);
                break;
            case Surface::Box: best.objectNormal = boxNormal(best.objectPoint); break;
            }
        }
    }
    return best;
}

// Ray-casts row y into `hits` (rows are disjoint, so any number of threads
// can fill different rows at once).
void castRow(const Scene &scene, const std::vector<PreparedObject> &objects, SceneHits &hits, int y)
{
    for (int x = 0; x < hits.width; ++x) {
        const Ray ray = cameraRay(scene.camera, x, y, hits.width, hits.height);
        const Hit hit =
            nearestHit<true>(objects, ray.direction, scene.camera.nearPlane, scene.camera.farPlane);
        if (!hit.object)
            continue;
        ReferenceHit &out = hits.hits[std::size_t(y) * std::size_t(hits.width) + std::size_t(x)];
        out.object = hit.object->index;
        out.triangle = hit.triangle;
        out.depth = hit.t;
        out.point = hit.objectPoint;
        out.normal = hit.objectNormal;
        out.barycentric = hit.barycentric;
    }
}

} // namespace

Result<SceneHits> castSceneHits(const Scene &scene,
                                const std::vector<std::shared_ptr<const MeshData>> &objectMeshes,
                                int width, int height, const std::function<bool(double)> &progress)
{
    if (width <= 0 || height <= 0)
        return fail(
            MeshRaycasterWords::tr("Invalid reference image size %1x%2").arg(width).arg(height));
    std::vector<PreparedObject> objects;
    if (const Result<> prepared =
            prepareObjects(scene, objectMeshes, double(width) / double(height), objects, progress);
        !prepared)
        return fail(prepared.error());

    SceneHits hits;
    hits.width = width;
    hits.height = height;
    hits.objects.resize(scene.objects.size());
    for (const PreparedObject &object : objects) {
        SceneHits::Object &o = hits.objects[std::size_t(object.index)];
        o.modelView = object.modelView;
        o.normalMatrix = object.normalMatrix;
        o.model = object.model;
        if (object.surface == Surface::Mesh)
            o.mesh = objectMeshes[std::size_t(object.index)];
    }
    hits.hits.resize(std::size_t(width) * std::size_t(height));
    const bool done = forEachRowInParallel(
        height, [&](int y) { castRow(scene, objects, hits, y); },
        [&](double fraction) { return !progress || progress(0.1 + 0.9 * fraction); });
    if (!done)
        return fail(QStringLiteral("cancelled"));
    return hits;
}

Result<ReferenceImage> raycastSceneMeshes(
    const Scene &scene, const std::vector<std::shared_ptr<const MeshData>> &objectMeshes, int width,
    int height, const ReferenceShader &shader, const std::function<bool(double)> &progress)
{
    const Result<SceneHits> hits = castSceneHits(scene, objectMeshes, width, height, progress);
    if (!hits)
        return fail(hits.error());
    return shadeSceneHits(*hits, scene, shader);
}

Result<ReferenceImage> raycastScene(const Scene &scene, int width, int height,
                                    const ReferenceShader &shader,
                                    const QHash<QString, QString> &standIns)
{
    Scene analytic = scene;
    for (SceneObject &object : analytic.objects)
        object.mesh = standIns.value(object.mesh, object.mesh);
    return raycastSceneMeshes(analytic,
                              std::vector<std::shared_ptr<const MeshData>>(analytic.objects.size()),
                              width, height, shader);
}

Result<ReferenceImage> raycastScene(const Scene &scene, int width, int height,
                                    const QHash<QString, QString> &standIns)
{
    return raycastScene(scene, width, height, ReferenceShading::Phong, standIns);
}

struct SceneDepthCaster::Objects {
    std::vector<PreparedObject> prepared;
};

SceneDepthCaster::SceneDepthCaster() = default;
SceneDepthCaster::~SceneDepthCaster() = default;

Result<std::unique_ptr<SceneDepthCaster>> SceneDepthCaster::create(
    const Scene &scene, const std::vector<std::shared_ptr<const MeshData>> &objectMeshes, int width,
    int height)
{
    if (width <= 0 || height <= 0)
        return fail(
            MeshRaycasterWords::tr("Invalid reference image size %1x%2").arg(width).arg(height));
    std::unique_ptr<SceneDepthCaster> caster(new SceneDepthCaster);
    caster->m_objects = std::make_unique<Objects>();
    if (const Result<> prepared = prepareObjects(
            scene, objectMeshes, double(width) / double(height), caster->m_objects->prepared, {});
        !prepared)
        return fail(prepared.error());
    for (PreparedObject &object : caster->m_objects->prepared) {
        object.mesh = nullptr;     // normals are never looked up here, and
        object.material = nullptr; // nothing may point into the caller's data
    }
    caster->m_width = width;
    caster->m_height = height;
    caster->m_tanHalfFov = std::tan(glm::radians(scene.camera.fovDeg) * 0.5);
    caster->m_nearPlane = scene.camera.nearPlane;
    caster->m_farPlane = scene.camera.farPlane;
    return caster;
}

double SceneDepthCaster::depthAt(double px, double py) const
{
    // cameraRay()'s arithmetic, term for term, so that a pixel centre gives
    // bit for bit the ray (and the depth) of raycastSceneMeshes().
    const double aspect = double(m_width) / double(m_height);
    const double ndcX = 2.0 * px / m_width - 1.0;
    const double ndcY = 1.0 - 2.0 * py / m_height;
    const glm::dvec3 direction(ndcX * m_tanHalfFov * aspect, ndcY * m_tanHalfFov, -1.0);
    return nearestHit<false>(m_objects->prepared, direction, m_nearPlane, m_farPlane).t;
}

} // namespace phonglab
