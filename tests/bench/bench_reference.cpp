// How fast the CPU reference answers: the analytic ray-caster (sphere and
// torus), the mesh ray-caster on the default scene, and one BVH over the
// bench's full-resolution mesh. Figures, not limits: each line also gives a
// ratio against a peer measured in the same run, since machines are noisy.
//
//   build/tests/bench/bench_reference [--size N]

#include "BenchHelpers.h"
#include "core/reference/AnalyticRaycaster.h"
#include "core/reference/MeshBvh.h"
#include "core/reference/MeshRaycaster.h"
#include "core/scene/ResourcePaths.h"
#include "core/scene/SceneJson.h"
#include "mesh/import/BuiltinMeshes.h"
#include "mesh/loading/SceneMeshes.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <cstdio>
#include <random>
#include <thread>

using namespace phonglab;

namespace {

double msOf(const std::function<void()> &work)
{
    QElapsedTimer timer;
    timer.start();
    work();
    return double(timer.nsecsElapsed()) / 1e6;
}

// Rays from outside the mesh's bounds towards points inside them.
std::vector<Ray> raysThrough(const MeshData &mesh, int count)
{
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::vec3 &p : mesh.positions) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    std::mt19937 random(1234);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const glm::dvec3 size = hi - lo, centre = 0.5 * (lo + hi);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 target = lo + size * glm::dvec3(unit(random), unit(random), unit(random));
        const glm::dvec3 origin = centre
            + 2.0 * glm::length(size)
                * glm::normalize(
                    glm::dvec3(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5));
        rays.push_back(Ray{origin, target - origin});
    }
    return rays;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.addHelpOption();
    parser.addOption({QStringLiteral("size"), QStringLiteral("Image side in pixels (default 256)."),
                      QStringLiteral("N"), QStringLiteral("256")});
    parser.process(app);
    const int side = std::max(16, parser.value(QStringLiteral("size")).toInt());
    std::printf("CPU reference on %u threads, %dx%d\n",
                std::max(1u, std::thread::hardware_concurrency()), side, side);

    const ReferenceShader phong(ReferenceShading::Phong);
    const double sphereMs = msOf([&] {
        (void)raycastScene(bench::litObjectScene(QStringLiteral("builtin:sphere")), side, side);
    });
    const double torusMs = msOf([&] {
        (void)raycastScene(bench::litObjectScene(QStringLiteral("builtin:torus")), side, side);
    });
    std::printf("analytic sphere      %8.1f ms\n", sphereMs);
    std::printf("analytic torus       %8.1f ms  (%.2fx the sphere: a quartic per ray)\n", torusMs,
                torusMs / sphereMs);

    const std::optional<bench::LoadedScene> loaded = bench::loadDefaultScene();
    if (!loaded)
        return 1;
    std::vector<std::shared_ptr<const MeshData>> perObject;
    std::size_t triangles = 0;
    for (const SceneObject &object : loaded->scene.objects) {
        perObject.push_back(loaded->meshes.entries.value(meshKey(loaded->scene, object)).mesh);
        triangles += perObject.back() ? perObject.back()->triangleCount() : 0;
    }
    const double sceneMs =
        msOf([&] { (void)raycastSceneMeshes(loaded->scene, perObject, side, side, phong); });
    std::printf("default scene meshes %8.1f ms  (%zu triangles; %.2fx the analytic sphere)\n",
                sceneMs, triangles, sceneMs / sphereMs);

    const MeshData big = makeUvSphere(1024, 640);
    std::optional<MeshBvh> bvh;
    const double buildMs = msOf([&] { bvh.emplace(big); });
    const std::vector<Ray> rays = raysThrough(big, 100000);
    int hits = 0;
    const double queryMs = msOf([&] {
        for (const Ray &ray : rays)
            hits += bvh->closestHit(ray, 0.0, 1e30).has_value();
    });
    std::printf("BVH build            %8.1f ms  (%zu triangles, %zu nodes, depth %d)\n", buildMs,
                big.triangleCount(), bvh->nodeCount(), bvh->depth());
    std::printf("100k rays            %8.1f ms  (%d hits; %.0f ns a ray, one thread)\n", queryMs,
                hits, queryMs * 1e6 / double(rays.size()));
    return 0;
}
