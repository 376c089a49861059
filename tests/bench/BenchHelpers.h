#pragma once
#include "core/scene/ResourcePaths.h"
#include "core/scene/SceneJson.h"
#include "mesh/loading/SceneMeshes.h"

#include <QByteArray>
#include <QFile>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

// What the latency benchmarks share.
namespace phonglab::bench {

// The value at fraction p (0..1) of the sorted samples, nearest rank; 0 when empty.
inline double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t rank = std::size_t(std::ceil(p * double(v.size())));
    return v[std::min(v.size() - 1, rank > 0 ? rank - 1 : 0)];
}

// The shipped Phong fragment shader with its output scaled by `k`: a new
// text, so a new program, for every k.
inline QByteArray editedFragment(double k)
{
    QFile file(shaderPath(QStringLiteral("phong.frag")));
    file.open(QIODevice::ReadOnly);
    QByteArray text = file.readAll();
    text.replace("fragColor = vec4(I, 1.0);",
                 "fragColor = vec4(I * " + QByteArray::number(k, 'f', 6) + ", 1.0);");
    return text;
}

// One object, turned so that no symmetry axis faces the camera, under one
// white light: the scene the reference and scaling benches time.
inline Scene litObjectScene(const QString &mesh)
{
    Scene scene;
    SceneObject object;
    object.mesh = mesh;
    object.transform.rotateDeg = {60.0, 0.0, 20.0};
    scene.objects.push_back(object);
    PointLight light;
    light.position = {3.0, 4.0, 5.0};
    scene.lights.push_back(light);
    return scene;
}

// The shipped default scene and its meshes, loaded in this process; nullopt
// after saying why on stderr.
struct LoadedScene {
    Scene scene;
    SceneMeshes meshes;
};
inline std::optional<LoadedScene> loadDefaultScene()
{
    const SceneLoadResult loaded = loadSceneFile(assetPath(QStringLiteral("scenes/default.json")));
    if (!loaded.ok()) {
        std::fprintf(stderr, "%s\n", qPrintable(loaded.error));
        return std::nullopt;
    }
    SceneMeshes meshes = loadSceneMeshes(*loaded.scene);
    if (!meshes.ok()) {
        std::fprintf(stderr, "%s\n", qPrintable(meshes.error));
        return std::nullopt;
    }
    return LoadedScene{*loaded.scene, std::move(meshes)};
}

} // namespace phonglab::bench
