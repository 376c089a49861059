#include "ResourcePaths.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace phonglab {

namespace {

// The folder of the running executable, with or without a Q*Application.
QString executableDir()
{
    if (QCoreApplication::instance())
        return QCoreApplication::applicationDirPath();
    return QFileInfo(QStringLiteral("/proc/self/exe"))
        .canonicalFilePath()
        .section(QLatin1Char('/'), 0, -2);
}

// Only an executable of the build tree may read the source tree it was built
// from: an installed one, wherever its prefix was moved, finds its files
// beside itself and never a path of the machine that built it.
bool runsFromBuildTree(const QString &exeDir)
{
    const QString buildDir = QFileInfo(QStringLiteral(PHONGLAB_BUILD_DIR)).canonicalFilePath();
    const QString dir = QFileInfo(exeDir).canonicalFilePath();
    return !buildDir.isEmpty() && (dir == buildDir || dir.startsWith(buildDir + QLatin1Char('/')));
}

// The search order, first match wins.
QStringList searchFolders(const char *envVar, const QString &folder, const char *sourceDir)
{
    QStringList dirs;
    const QString fromEnv = qEnvironmentVariable(envVar);
    if (!fromEnv.isEmpty())
        dirs << fromEnv;
    const QString exeDir = executableDir();
    if (!exeDir.isEmpty())
        dirs << exeDir + QLatin1Char('/') + folder << exeDir + QStringLiteral("/../") + folder
             << exeDir + QStringLiteral("/../share/phonglab/") + folder;
    if (exeDir.isEmpty() || runsFromBuildTree(exeDir))
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

bool isShippedScene(const QString &path)
{
    const QString scenes =
        QFileInfo(QFileInfo(defaultScenePath()).absolutePath()).canonicalFilePath();
    const QString folder = QFileInfo(QFileInfo(path).absolutePath()).canonicalFilePath();
    return !scenes.isEmpty() && folder == scenes;
}

} // namespace phonglab
