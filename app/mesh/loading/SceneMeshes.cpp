#include "SceneMeshes.h"

#include "core/support/Vec3Key.h"

#include "mesh/detail/MeshDecimation.h"
#include "mesh/import/BuiltinMeshes.h"

#include <QElapsedTimer>
#include <QLocale>
#include <QSet>

#include <algorithm>
#include <array>
#include <bit>

namespace phonglab {

namespace {

QString detailSuffix(const SceneObject &object)
{
    if (object.autoDetail)
        return QStringLiteral("|detail=auto");
    const double detail = object.detail;
    if (detail == 1.0)
        return {};
    // Shortest round-trip form: "0.25", and two details differ in the key
    // exactly when they differ as numbers.
    return QStringLiteral("|detail=")
        + QString::number(detail, 'g', QLocale::FloatingPointShortest);
}

void fillDrawnStats(const MeshData &mesh, MeshStats &s, bool countSplits)
{
    s.vertices = qint64(mesh.positions.size());
    s.triangles = qint64(mesh.triangleCount());
    if (countSplits) {
        // GPU vertices beyond one per position (Vec3Key: what MeshBuilder
        // welds as one).
        std::vector<Vec3Key> keys;
        keys.reserve(mesh.positions.size());
        for (const glm::vec3 &p : mesh.positions)
            keys.push_back(vec3Key(p));
        std::sort(keys.begin(), keys.end());
        const auto distinct = qint64(std::unique(keys.begin(), keys.end()) - keys.begin());
        s.splitVertices = s.vertices - distinct;
    }
    if (!mesh.positions.empty()) {
        s.boundsMin = s.boundsMax = mesh.positions.front();
        for (const glm::vec3 &p : mesh.positions) {
            s.boundsMin = glm::min(s.boundsMin, p);
            s.boundsMax = glm::max(s.boundsMax, p);
        }
    }
}

// Replaces the full mesh with the one drawn at `detail`: builtins
// tessellated coarser, files decimated (the mesh cache keeps the full one).
// False when `progress` cancelled the decimation.
bool applyDetail(MeshLoadResult &loaded, const QString &spec, double detail,
                 const LoadProgress &progress)
{
    if (detail == 1.0 || !loaded.mesh)
        return true;
    QElapsedTimer timer;
    timer.start();
    MeshStats &s = loaded.stats;
    s.detail = detail;
    s.fullTriangles = s.triangles;
    if (isBuiltinMeshSpec(spec)) {
        if (std::optional<MeshData> coarse = builtinMesh(spec, detail))
            *loaded.mesh = std::move(*coarse);
        fillDrawnStats(*loaded.mesh, s, false);
        s.fileVertices = s.vertices; // as loadMesh counts builtins
        s.fileFaces = s.triangles;
    } else {
        bool cancelled = false;
        const DecimationProgress step = [&](double f) {
            cancelled = progress && !progress(f);
            return !cancelled;
        };
        DecimatedMesh coarse =
            decimateMesh(*loaded.mesh, detail, progress ? step : DecimationProgress{});
        if (cancelled)
            return false;
        *loaded.mesh = std::move(coarse.mesh);
        if (!coarse.note.isEmpty())
            loaded.warnings << QStringLiteral("detail %1: %2").arg(detail).arg(coarse.note);
        fillDrawnStats(*loaded.mesh, s, true);
        // Decimation keeps a closed surface closed unless it had to leave
        // faces out; check rather than assume (back faces are culled on it).
        s.closed = s.closed && isClosedMesh(*loaded.mesh);
    }
    s.loadMs += timer.nsecsElapsed() / 1e6;
    return true;
}

} // namespace

QString meshKey(const Scene &scene, const SceneObject &object)
{
    const QString spec = scene.resolveMeshPath(object.mesh);
    if (spec.startsWith(QLatin1String("builtin:")))
        return spec + detailSuffix(object); // analytic normals: the options do not apply
    QString key = spec + QLatin1Char('|') + normalMethodName(object.normals.method);
    if (object.normals.creaseAngleDeg)
        key += QLatin1Char('|') + QString::number(*object.normals.creaseAngleDeg, 'g', 17);
    return key + detailSuffix(object);
}

std::vector<glm::dvec3> objectBoundsCorners(const Scene &scene,
                                            const QHash<QString, SceneMeshes::Entry> &entries)
{
    std::vector<glm::dvec3> corners;
    for (const SceneObject &object : scene.objects) {
        const auto entry = entries.constFind(meshKey(scene, object));
        if (entry == entries.constEnd())
            continue;
        const glm::dvec3 lo(entry->stats.boundsMin), hi(entry->stats.boundsMax);
        const glm::dmat4 model = object.transform.matrix();
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                               corner & 4 ? hi.z : lo.z};
            corners.push_back(glm::dvec3(model * glm::dvec4(p, 1.0)));
        }
    }
    return corners;
}

SceneMeshes loadSceneMeshes(const Scene &scene, const QSet<QString> &alreadyLoaded,
                            const LoadProgress &progress)
{
    SceneMeshes result;
    // Distinct keys to load, in object order.
    QList<const SceneObject *> todo;
    QSet<QString> seen = alreadyLoaded;
    for (const SceneObject &object : scene.objects) {
        const QString key = meshKey(scene, object);
        if (!seen.contains(key)) {
            seen.insert(key);
            todo << &object;
        }
    }
    for (qsizetype i = 0; i < todo.size(); ++i) {
        const SceneObject &object = *todo[i];
        // The full mesh first (what the mesh cache holds), then its level of
        // detail: half of this object's share of the progress bar each when
        // it is decimated.
        const QString spec = scene.resolveMeshPath(object.mesh);
        const bool decimated =
            object.autoDetail || (object.detail != 1.0 && !isBuiltinMeshSpec(spec));
        const double from = double(i) / todo.size(), to = double(i + 1) / todo.size();
        const double split = decimated ? 0.5 * (from + to) : to;
        const auto part = [&progress](double a, double b) -> LoadProgress {
            if (!progress)
                return {};
            return [&progress, a, b](double f) { return progress(a + (b - a) * f); };
        };
        MeshLoadResult loaded = loadMesh(spec, object.normals, part(from, split));
        if (!loaded.ok()) {
            result.entries.clear();
            result.error = loaded.error;
            return result;
        }
        if (!applyDetail(loaded, spec, object.detail, part(split, to))) {
            result.entries.clear();
            result.error = QStringLiteral("cancelled");
            return result;
        }
        SceneMeshes::Entry entry;
        entry.mesh = std::make_shared<const MeshData>(std::move(*loaded.mesh));
        if (object.autoDetail) {
            auto levels =
                std::make_shared<DetailLevels>(buildDetailLevels(*entry.mesh, part(split, to)));
            if (levels->empty()) {
                result.entries.clear();
                result.error = QStringLiteral("cancelled");
                return result;
            }
            entry.levels = std::move(levels);
        }
        entry.stats = loaded.stats;
        entry.warnings = loaded.warnings;
        result.entries.insert(meshKey(scene, object), std::move(entry));
    }
    return result;
}

} // namespace phonglab
