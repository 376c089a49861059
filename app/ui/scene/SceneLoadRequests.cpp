#include "SceneLoadRequests.h"

#include "FileTypes.h"
#include "MeshPlacement.h"
#include "bench/BenchResult.h"

#include <QFileInfo>

namespace phonglab {

SceneLoadRequest sceneFileRequest(const QString &path, const Scene &scene)
{
    SceneLoadRequest request;
    request.scene = scene;
    request.label = QFileInfo(path).fileName();
    return request;
}

SceneLoadRequest meshFilesRequest(const Scene &current, const QStringList &paths)
{
    SceneLoadRequest request;
    request.scene = sceneWithMeshes(current, paths);
    request.label = paths.size() == 1 ? QFileInfo(paths.front()).fileName()
                                      : QObject::tr("%1 meshes").arg(paths.size());
    // Fitted into the scene shown when loading ends: the camera may have
    // moved meanwhile, and the bounds are only known now.
    request.finish = [paths](const Scene &shown, const SceneLoadRequest::MeshInfo &meshes) {
        return fittedSideBySide(sceneWithMeshes(shown, paths), meshes);
    };
    return request;
}

SceneLoadRequest normalsRequest(const Scene &current, int objectIndex, const NormalOptions &options)
{
    const QString mesh = current.objects[objectIndex].mesh;
    SceneLoadRequest request;
    request.scene = current;
    request.scene.objects[objectIndex].normals = options;
    request.label = QObject::tr("%1 (%2 normals)")
                        .arg(QFileInfo(mesh).fileName(), normalMethodName(options.method));
    request.finish = [objectIndex, options, mesh, requested = request.scene](
                         const Scene &shown, const SceneLoadRequest::MeshInfo &) {
        // Objects only change through loads, one at a time, so `shown` still
        // has this object; anything else gets the scene as requested.
        if (objectIndex >= int(shown.objects.size()) || shown.objects[objectIndex].mesh != mesh)
            return requested;
        Scene scene = shown; // keeps the camera as it is now
        scene.objects[objectIndex].normals = options;
        return scene;
    };
    return request;
}

SceneLoadRequest fitRequest(const Scene &current, ShadingMethod method, double detail)
{
    auto apply = [method, detail](Scene scene) {
        scene.shading = method;
        for (SceneObject &object : scene.objects)
            object.detail = detail;
        return scene;
    };
    SceneLoadRequest request;
    request.scene = apply(current);
    request.label = QObject::tr("%1 at %2 detail").arg(shadingName(method), detailPercent(detail));
    // Applied to the scene on screen when loading ends: the camera and lights
    // may have moved meanwhile. Objects only change through loads, so its
    // objects are still the ones loaded here.
    request.finish = [apply, requested = request.scene](const Scene &shown,
                                                        const SceneLoadRequest::MeshInfo &) {
        return shown.objects.size() == requested.objects.size() ? apply(shown) : requested;
    };
    return request;
}

SceneLoadRequest autoDetailRequest(const Scene &current, bool on)
{
    auto apply = [on](Scene scene) {
        for (SceneObject &object : scene.objects) {
            object.autoDetail = on;
            object.detail = 1.0;
        }
        return scene;
    };
    SceneLoadRequest request;
    request.scene = apply(current);
    request.label = on ? QObject::tr("levels of detail") : QObject::tr("full detail");
    request.finish = [apply, requested = request.scene](const Scene &shown,
                                                        const SceneLoadRequest::MeshInfo &) {
        return shown.objects.size() == requested.objects.size() ? apply(shown) : requested;
    };
    return request;
}

} // namespace phonglab
