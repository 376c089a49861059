#pragma once
#include "core/check/ShaderCheck.h"
#include "core/scene/SceneJson.h"
#include "mesh/loading/SceneMeshes.h"

#include "TestPaths.h"

#include <QTest>

// The shipped scene `phonglab check` is designed on (assets/scenes/check.json)
// and the reference a check of it compares with.
namespace phonglab::test {

inline constexpr int kCheckWidth = 320;
inline constexpr int kCheckHeight = 240;

inline Scene loadCheckScene()
{
    const SceneLoadResult loaded =
        loadSceneFile(sourcePath(QStringLiteral("assets/scenes/check.json")));
    if (!loaded.ok())
        qFatal("assets/scenes/check.json: %s", qPrintable(loaded.error));
    return *loaded.scene;
}

// Every object's triangle mesh, builtins included, as `phonglab check` casts them.
inline std::vector<std::shared_ptr<const MeshData>> checkMeshes(const Scene &scene)
{
    const SceneMeshes meshes = loadSceneMeshes(scene);
    if (!meshes.ok())
        qFatal("meshes: %s", qPrintable(meshes.error));
    std::vector<std::shared_ptr<const MeshData>> out;
    for (const SceneObject &object : scene.objects)
        out.push_back(meshes.entries.value(meshKey(scene, object)).mesh);
    return out;
}

inline CheckReference makeTestCheckReference(const Scene &scene, int width = kCheckWidth,
                                             int height = kCheckHeight)
{
    Result<CheckReference> r = makeCheckReference(scene, checkMeshes(scene), width, height);
    if (!r)
        qFatal("check reference: %s", qPrintable(r.error()));
    return std::move(*r);
}

} // namespace phonglab::test
