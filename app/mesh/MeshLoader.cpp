#include "MeshLoader.h"

#include "BuiltinMeshes.h"

#include <QElapsedTimer>

namespace phonglab {

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
        result.error = QStringLiteral("%1: unknown builtin mesh (known: builtin:sphere, builtin:torus, builtin:cube)").arg(spec);
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

} // namespace

MeshLoadResult loadMesh(const QString &spec, const NormalOptions &normals, const LoadProgress &progress)
{
    QElapsedTimer timer;
    timer.start();
    if (isBuiltinMeshSpec(spec)) {
        MeshLoadResult result = loadBuiltin(spec);
        result.stats.loadMs = timer.nsecsElapsed() / 1e6;
        return result;
    }

    MeshLoadResult result;
    result.error = QStringLiteral("%1: mesh files cannot be loaded yet").arg(spec);
    return result;
}

} // namespace phonglab
