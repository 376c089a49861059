#include "Scene.h"

#include <QDir>

namespace phonglab {

QString Scene::resolveMeshPath(const QString &mesh) const
{
    if (mesh.startsWith(QLatin1String("builtin:")) || QDir::isAbsolutePath(mesh) || baseDir.isEmpty())
        return mesh;
    return QDir(baseDir).filePath(mesh);
}

bool Scene::operator==(const Scene &other) const
{
    return objects == other.objects && camera == other.camera && ambient == other.ambient
        && lights == other.lights && shading == other.shading && background == other.background;
}

} // namespace phonglab
