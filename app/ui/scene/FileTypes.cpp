#include "FileTypes.h"

#include <QFileInfo>
#include <QObject>
#include <algorithm>

namespace phonglab {

bool isSceneFile(const QString &path)
{
    return QFileInfo(path).suffix().compare(QLatin1String("json"), Qt::CaseInsensitive) == 0;
}

QString whyNotOpenable(const QStringList &paths)
{
    if (paths.isEmpty())
        return QObject::tr("No file to open.");
    QStringList unsupported;
    for (const QString &path : paths)
        if (!isSceneFile(path) && !isMeshFile(path))
            unsupported << path;
    if (!unsupported.isEmpty())
        return QObject::tr("%1: PhongLab cannot open this kind of file. It opens scenes (.json) "
                           "and meshes (.%2).")
            .arg(fileNameList(unsupported), meshFileSuffixes().join(QStringLiteral(", .")));
    if (paths.size() > 1 && std::any_of(paths.begin(), paths.end(), isSceneFile))
        return QObject::tr(
                   "%1: a scene file opens on its own. Open one scene, or any number of meshes.")
            .arg(fileNameList(paths));
    return {};
}

QString fileNameList(const QStringList &paths)
{
    QStringList names;
    for (const QString &path : paths)
        names << QFileInfo(path).fileName();
    return names.join(QStringLiteral(", "));
}

QString sceneFileFilter()
{
    return QObject::tr("PhongLab scenes (*.json);;All files (*)");
}

QString meshFileFilter()
{
    QStringList patterns;
    for (const QString &suffix : meshFileSuffixes())
        patterns << QStringLiteral("*.") + suffix;
    return QObject::tr("Meshes (%1);;All files (*)").arg(patterns.join(QLatin1Char(' ')));
}

} // namespace phonglab
