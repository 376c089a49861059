// Which simplifier should make the levels of detail: OpenMesh's
// Decimater (quadrics, what decimateMesh uses today) against meshoptimizer's
// meshopt_simplify, on the same meshes at the same triangle targets, in one
// run. Prints figures; not a test.
//
//   build/tests/bench/bench_simplify [MESH.obj ...]
//
// For each mesh (the default scene's tree and cloud, the builtin sphere, and
// any OBJ given) and each fraction, both simplifiers' time and triangles,
// meshoptimizer's own error estimate, and the deviation both are measured
// by alike: from every vertex of the full mesh, along its normal (both ways),
// the distance to the simplified surface (MeshBvh), as max and mean, in
// per mille of the bounding-box diagonal. Neither moves a vertex, so the
// simplified surface's own vertices lie on the original exactly.
#include "BenchHelpers.h"
#include "core/reference/MeshBvh.h"
#include "core/scene/ResourcePaths.h"
#include "core/scene/SceneJson.h"
#include "mesh/detail/MeshDecimation.h"
#include "mesh/import/BuiltinMeshes.h"
#include "mesh/loading/SceneMeshes.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <algorithm>
#include <cstdio>
#include <meshoptimizer.h>
#include <vector>

using namespace phonglab;

namespace {

struct Deviation {
    double maxPermille = 0.0;
    double meanPermille = 0.0;
};

double diagonal(const MeshData &mesh)
{
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::vec3 &p : mesh.positions) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    return glm::length(hi - lo);
}

// How far the simplified surface lies from the full mesh's vertices, along
// each vertex normal; a ray that meets nothing within the diagonal counts
// as one diagonal away (a hole).
Deviation deviation(const MeshData &full, const MeshData &simplified)
{
    const double diag = diagonal(full);
    const MeshBvh bvh(simplified);
    double worst = 0.0, sum = 0.0;
    for (std::size_t i = 0; i < full.positions.size(); ++i) {
        const glm::dvec3 p(full.positions[i]);
        const glm::dvec3 n = glm::normalize(glm::dvec3(full.normals[i]));
        double nearest = diag;
        for (const double side : {1.0, -1.0}) {
            const Ray ray{p, side * n};
            if (const auto hit = bvh.closestHit(ray, 0.0, diag))
                nearest = std::min(nearest, hit->t);
        }
        worst = std::max(worst, nearest);
        sum += nearest;
    }
    const double count = double(std::max<std::size_t>(1, full.positions.size()));
    return {1000.0 * worst / diag, 1000.0 * sum / count / diag};
}

struct Simplified {
    MeshData mesh;
    double ms = 0.0;
    double ownErrorPermille = -1.0; // the simplifier's own estimate; < 0: none
};

Simplified withOpenMesh(const MeshData &full, double fraction)
{
    QElapsedTimer clock;
    clock.start();
    DecimatedMesh decimated = decimateMesh(full, fraction);
    return {std::move(decimated.mesh), double(clock.nsecsElapsed()) / 1e6, -1.0};
}

// Welded by position first (MeshData splits a vertex per normal, which
// meshoptimizer would take as seams), so both see one surface.
Simplified withMeshoptimizer(const MeshData &full, double fraction)
{
    QElapsedTimer clock;
    clock.start();
    const float *positions = &full.positions.front().x;
    const std::size_t vertexCount = full.positions.size();
    std::vector<unsigned int> shadow(full.indices.size());
    meshopt_generateShadowIndexBuffer(shadow.data(), full.indices.data(), full.indices.size(),
                                      positions, vertexCount, sizeof(glm::vec3), sizeof(glm::vec3));
    const auto target = std::size_t(double(full.indices.size() / 3) * fraction) * 3;
    std::vector<unsigned int> simplified(shadow.size());
    float relativeError = 0.0f;
    simplified.resize(meshopt_simplify(simplified.data(), shadow.data(), shadow.size(), positions,
                                       vertexCount, sizeof(glm::vec3), target, 1.0f, 0,
                                       &relativeError));
    Simplified out;
    out.ms =
        double(clock.nsecsElapsed()) / 1e6; // weld + simplify; the copies below are the bench's
    const float scale = meshopt_simplifyScale(positions, vertexCount, sizeof(glm::vec3));
    out.mesh.positions = full.positions; // unused vertices stay: the draw never reads them
    out.mesh.normals = full.normals;
    out.mesh.indices.assign(simplified.begin(), simplified.end());
    out.ownErrorPermille = 1000.0 * double(relativeError * scale) / diagonal(full);
    return out;
}

void compare(const QString &name, const MeshData &full)
{
    std::printf("\n%s: %zu triangles, %zu vertices\n", qPrintable(name), full.triangleCount(),
                full.positions.size());
    std::printf(
        "| fraction | simplifier | triangles | ms | own error ‰ | deviation max ‰ | mean ‰ |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (const double fraction : {0.5, 0.25, 1.0 / 16}) {
        const Simplified om = withOpenMesh(full, fraction);
        const Simplified mo = withMeshoptimizer(full, fraction);
        for (const auto &[label, s] :
             {std::pair{"OpenMesh Decimater", &om}, std::pair{"meshoptimizer", &mo}}) {
            const Deviation d = deviation(full, s->mesh);
            const QString own = s->ownErrorPermille < 0.0
                ? QStringLiteral("—")
                : QString::number(s->ownErrorPermille, 'f', 3);
            std::printf("| %.4g | %s | %zu | %.1f | %s | %.3f | %.4f |\n", fraction, label,
                        s->mesh.triangleCount(), s->ms, qPrintable(own), d.maxPermille,
                        d.meanPermille);
        }
        std::printf("| %.4g | time meshoptimizer / OpenMesh | | %.2fx | | | |\n", fraction,
                    mo.ms / std::max(1e-9, om.ms));
    }
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const std::optional<bench::LoadedScene> loaded = bench::loadDefaultScene();
    if (!loaded)
        return 1;
    for (const SceneObject &object : loaded->scene.objects)
        if (const auto mesh = loaded->meshes.entries.value(meshKey(loaded->scene, object)).mesh)
            compare(QFileInfo(object.mesh).fileName(), *mesh);
    compare(QStringLiteral("builtin sphere"), makeUvSphere(256, 128));
    for (int i = 1; i < argc; ++i) {
        Scene scene;
        SceneObject object;
        object.mesh = QFileInfo(QString::fromLocal8Bit(argv[i])).absoluteFilePath();
        scene.objects.push_back(object);
        const SceneMeshes extra = loadSceneMeshes(scene);
        if (!extra.ok()) {
            std::fprintf(stderr, "%s\n", qPrintable(extra.error));
            return 1;
        }
        compare(QFileInfo(object.mesh).fileName(), *extra.entries.begin()->mesh);
    }
    return 0;
}
