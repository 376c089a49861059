#include "ResourcePaths.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace phonglab {

namespace {

QString findFile(const char *envVar, const QString &folder, const char *sourceDir, const QString &name)
{
    QStringList dirs;
    const QString fromEnv = qEnvironmentVariable(envVar);
    if (!fromEnv.isEmpty())
        dirs << fromEnv;
    if (QCoreApplication::instance()) {
        const QString appDir = QCoreApplication::applicationDirPath();
        dirs << appDir + QLatin1Char('/') + folder << appDir + QStringLiteral("/../") + folder
             << appDir + QStringLiteral("/../share/phonglab/") + folder;
    }
    dirs << QString::fromUtf8(sourceDir);
    for (const QString &dir : dirs) {
        const QString candidate = QDir(dir).filePath(name);
        if (QFileInfo(candidate).isFile())
            return QDir::cleanPath(candidate);
    }
    return QStringLiteral(":/%1/%2").arg(folder, name);
}

} // namespace

QString shaderPath(const QString &fileName)
{
    return findFile("PHONGLAB_SHADER_DIR", QStringLiteral("shaders"), PHONGLAB_SOURCE_SHADER_DIR, fileName);
}

QString assetPath(const QString &relativePath)
{
    return findFile("PHONGLAB_ASSET_DIR", QStringLiteral("assets"), PHONGLAB_SOURCE_ASSET_DIR, relativePath);
}

QString defaultScenePath()
{
    return assetPath(QStringLiteral("scenes/default.json"));
}

} // namespace phonglab
