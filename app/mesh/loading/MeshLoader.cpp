#include "MeshLoader.h"

#include "MeshCache.h"
#include "MeshImportProcess.h"
#include "mesh/import/BuiltinMeshes.h"
#include "mesh/import/MeshFileReader.h"
#include "mesh/import/MeshRepair.h"
#include "mesh/import/MeshTopology.h"
#include "mesh/normals/MeshBuilder.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <future>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct MeshLoaderWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::MeshLoader)
};

namespace {

void fillBounds(const MeshData &mesh, MeshStats &stats)
{
    if (mesh.positions.empty())
        return;
    stats.boundsMin = stats.boundsMax = mesh.positions.front();
    for (const glm::vec3 &p : mesh.positions) {
        stats.boundsMin = glm::min(stats.boundsMin, p);
        stats.boundsMax = glm::max(stats.boundsMax, p);
    }
}

MeshLoadResult loadBuiltin(const QString &spec)
{
    MeshLoadResult result;
    result.mesh = builtinMesh(spec);
    if (!result.mesh) {
        result.error =
            MeshLoaderWords::tr(
                "%1: unknown builtin mesh (known: builtin:sphere, builtin:torus, builtin:cube)")
                .arg(spec);
        return result;
    }
    MeshStats &s = result.stats;
    s.vertices = qint64(result.mesh->positions.size());
    s.fileVertices = s.vertices;
    s.triangles = qint64(result.mesh->triangleCount());
    s.fileFaces = s.triangles;
    s.normalsFromFile = false; // analytic normals
    s.closed = true;
    fillBounds(*result.mesh, s);
    return result;
}

// Progress is split between reading (most of the time) and building.
LoadProgress scaled(const LoadProgress &progress, double from, double to)
{
    if (!progress)
        return {};
    return [=](double f) { return progress(from + (to - from) * f); };
}

} // namespace

MeshLoadResult importMeshFile(const QString &path, const NormalOptions &normals,
                              const LoadProgress &progress)
{
    QElapsedTimer timer;
    timer.start();
    MeshLoadResult result;
    MeshReadResult read = readMeshFile(path, scaled(progress, 0.0, 0.8));
    result.warnings = read.warnings;
    if (!read.mesh) {
        result.error = QStringLiteral("%1: %2").arg(path, read.error);
        return result;
    }
    PolygonMesh &polygons = *read.mesh;
    const RepairReport repair = repairMesh(polygons);
    result.warnings += repair.warnings();
    if (polygons.faceCount() == 0) {
        result.error = MeshLoaderWords::tr("%1: no usable faces").arg(path);
        return result;
    }
    if (progress && !progress(0.85)) {
        result.error = QStringLiteral("cancelled");
        return result;
    }

    // Whether the surface is closed only reads the repaired polygons: it is
    // found on a second thread while the GPU arrays are built.
    std::future<bool> closed =
        std::async(std::launch::async, [&polygons] { return isClosedSurface(polygons); });
    BuiltMesh built = buildMeshData(polygons, normals);
    const bool isClosed = closed.get();
    result.warnings += built.warnings;
    if (!built.ok()) {
        result.error = QStringLiteral("%1: %2").arg(path, built.error);
        return result;
    }
    MeshData &mesh = built.mesh;
    MeshStats &s = result.stats;
    s = built.stats;
    s.fileFaces = qint64(polygons.faceCount());
    s.creaseAngleDeg = normals.creaseAngleDeg;
    s.closed = isClosed;
    result.mesh = std::move(mesh);
    if (progress)
        progress(1.0);
    s.loadMs = timer.nsecsElapsed() / 1e6;
    return result;
}

MeshLoadResult loadMesh(const QString &spec, const NormalOptions &normals,
                        const LoadProgress &progress)
{
    QElapsedTimer timer;
    timer.start();
    if (isBuiltinMeshSpec(spec)) {
        MeshLoadResult result = loadBuiltin(spec);
        result.stats.loadMs = timer.nsecsElapsed() / 1e6;
        return result;
    }
    if (auto cached = MeshCache::read(spec, normals)) {
        cached->stats.loadMs = timer.nsecsElapsed() / 1e6;
        if (progress)
            progress(1.0);
        return std::move(*cached);
    }
    // Not parsed here: the child writes the cache entry this process adopts.
    MeshLoadResult result = importMeshIsolated(spec, normals, progress);
    result.stats.loadMs = timer.nsecsElapsed() / 1e6;
    return result;
}

} // namespace phonglab
