#include "SceneMeshes.h"

#include <QSet>

namespace phonglab {

QString meshKey(const Scene &scene, const SceneObject &object)
{
    const QString spec = scene.resolveMeshPath(object.mesh);
    if (spec.startsWith(QLatin1String("builtin:")))
        return spec; // analytic normals: the options do not apply
    QString key = spec + QLatin1Char('|') + normalMethodName(object.normals.method);
    if (object.normals.creaseAngleDeg)
        key += QLatin1Char('|') + QString::number(*object.normals.creaseAngleDeg, 'g', 17);
    return key;
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
        LoadProgress part;
        if (progress) {
            const double from = double(i) / todo.size(), to = double(i + 1) / todo.size();
            part = [&progress, from, to](double f) { return progress(from + (to - from) * f); };
        }
        MeshLoadResult loaded = loadMesh(scene.resolveMeshPath(object.mesh), object.normals, part);
        if (!loaded.ok()) {
            result.entries.clear();
            result.error = loaded.error;
            return result;
        }
        SceneMeshes::Entry entry;
        entry.mesh = std::make_shared<const MeshData>(std::move(*loaded.mesh));
        entry.stats = loaded.stats;
        entry.warnings = loaded.warnings;
        result.entries.insert(meshKey(scene, object), std::move(entry));
    }
    return result;
}

} // namespace phonglab
