#include "MeshPlacement.h"

#include <QFileInfo>
#include <algorithm>

namespace phonglab {

Scene sceneWithMeshes(const Scene &base, const QStringList &paths)
{
    Scene scene = base;
    const Material material = base.objects.empty() ? Material() : base.objects.front().material;
    scene.objects.clear();
    for (const QString &path : paths) {
        SceneObject object;
        object.mesh = QFileInfo(path).absoluteFilePath();
        object.material = material;
        scene.objects.push_back(object);
    }
    return scene;
}

Transform fittedTransform(const MeshStats &stats, double xOffset)
{
    const glm::dvec3 lo(stats.boundsMin), hi(stats.boundsMax);
    const glm::dvec3 extent = hi - lo;
    const double largest = std::max({extent.x, extent.y, extent.z});
    // A degenerate mesh (one point) keeps its size; it is still centred.
    const double scale = largest > 0.0 ? kFittedMeshSize / largest : 1.0;
    Transform transform;
    transform.scale = glm::dvec3(scale);
    // The model matrix scales first, so the centre lands at scale · centre.
    transform.translate = glm::dvec3(xOffset, 0.0, 0.0) - scale * (lo + hi) * 0.5;
    return transform;
}

Scene fittedSideBySide(Scene scene, const QHash<QString, SceneMeshes::Entry> &meshes)
{
    const double count = double(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        SceneObject &object = scene.objects[i];
        const double xOffset = (double(i) - (count - 1.0) / 2.0) * kSideBySideSpacing;
        object.transform = fittedTransform(meshes.value(meshKey(scene, object)).stats, xOffset);
    }
    return scene;
}

} // namespace phonglab
