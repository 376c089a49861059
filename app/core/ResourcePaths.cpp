#include "ResourcePaths.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace phonglab {

namespace {

// The search order, first match wins.
QStringList searchFolders(const char *envVar, const QString &folder, const char *sourceDir)
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
    return dirs;
}

QString findFile(const char *envVar, const QString &folder, const char *sourceDir,
                 const QString &name)
{
    for (const QString &dir : searchFolders(envVar, folder, sourceDir)) {
        const QString candidate = QDir(dir).filePath(name);
        if (QFileInfo(candidate).isFile())
            return QDir::cleanPath(candidate);
    }
    return QStringLiteral(":/%1/%2").arg(folder, name);
}

} // namespace

QString shaderPath(const QString &fileName)
{
    return findFile("PHONGLAB_SHADER_DIR", QStringLiteral("shaders"), PHONGLAB_SOURCE_SHADER_DIR,
                    fileName);
}

QStringList shaderSearchFolders()
{
    return searchFolders("PHONGLAB_SHADER_DIR", QStringLiteral("shaders"),
                         PHONGLAB_SOURCE_SHADER_DIR);
}

QString shippedShaderPath(ShadingMethod method, ShaderStage stage)
{
    return shaderPath(shadingName(method) + stageSuffix(stage));
}

QString assetPath(const QString &relativePath)
{
    return findFile("PHONGLAB_ASSET_DIR", QStringLiteral("assets"), PHONGLAB_SOURCE_ASSET_DIR,
                    relativePath);
}

QString defaultScenePath()
{
    return assetPath(QStringLiteral("scenes/default.json"));
}

} // namespace phonglab
