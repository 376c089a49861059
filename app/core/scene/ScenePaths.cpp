#include "ScenePaths.h"

#include <QDir>
#include <QFileInfo>

namespace phonglab {

QStringList meshFileSuffixes()
{
    return {QStringLiteral("obj"), QStringLiteral("ply"), QStringLiteral("off"),
            QStringLiteral("stl"), QStringLiteral("om")};
}

bool isMeshFile(const QString &path)
{
    return meshFileSuffixes().contains(QFileInfo(path).suffix(), Qt::CaseInsensitive);
}

bool isWritableLocation(const QString &path)
{
    return !path.isEmpty() && !path.startsWith(QLatin1Char(':'));
}

Scene rebasedOnto(Scene scene, const QString &sceneFilePath)
{
    const QDir folder = QFileInfo(sceneFilePath).absoluteDir();
    for (SceneObject &object : scene.objects) {
        const QString resolved = scene.resolveMeshPath(object.mesh);
        if (resolved != object.mesh && isWritableLocation(resolved))
            object.mesh = folder.relativeFilePath(resolved);
    }
    scene.baseDir = folder.absolutePath();
    return scene;
}

QString pathFromScene(const QString &file, const QString &sceneFilePath)
{
    const QString absolute = QFileInfo(file).absoluteFilePath();
    const QString relative = QFileInfo(sceneFilePath).absoluteDir().relativeFilePath(absolute);
    return relative.startsWith(QLatin1String("..")) || QDir::isAbsolutePath(relative) ? absolute
                                                                                      : relative;
}

} // namespace phonglab
