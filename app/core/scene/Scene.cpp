#include "Scene.h"

#include <algorithm>

#include <QDir>

namespace phonglab {

QString Scene::resolveMeshPath(const QString &mesh) const
{
    if (mesh.startsWith(QLatin1String("builtin:")) || QDir::isAbsolutePath(mesh)
        || baseDir.isEmpty())
        return mesh;
    // cleanPath folds "scenes/../meshes": Qt resource paths (":/assets/...")
    // do not resolve ".." themselves.
    return QDir::cleanPath(QDir(baseDir).filePath(mesh));
}

int Scene::enabledLightCount() const
{
    return int(
        std::count_if(lights.begin(), lights.end(), [](const PointLight &l) { return l.enabled; }));
}

QString Scene::resolveShaderPath(const QString &shader) const
{
    if (shader.isEmpty() || QDir::isAbsolutePath(shader) || baseDir.isEmpty())
        return shader;
    return QDir::cleanPath(QDir(baseDir).filePath(shader));
}

bool Scene::operator==(const Scene &other) const
{
    return objects == other.objects && camera == other.camera && ambient == other.ambient
        && lights == other.lights && shading == other.shading && background == other.background
        && vertexShader == other.vertexShader && fragmentShader == other.fragmentShader
        && uniforms == other.uniforms && bindings == other.bindings && course == other.course
        && page == other.page;
}

} // namespace phonglab
