#include "SceneStages.h"

#include "CliCommon.h"
#include "core/ResourcePaths.h"
#include "render/ShaderSource.h"

#include <QSaveFile>

namespace phonglab::cli {

namespace {

QString stagePath(const QString &fromArgs, const QString &fromScene, const Scene &scene, bool methodChosen,
                  const QString &shipped)
{
    if (!fromArgs.isEmpty())
        return fromArgs;
    if (!fromScene.isEmpty() && !methodChosen)
        return scene.resolveShaderPath(fromScene);
    return shipped;
}

} // namespace

StageFiles chooseStageFiles(const Scene &scene, const QString &vertexArg, const QString &fragmentArg, bool methodChosen)
{
    return {stagePath(vertexArg, scene.vertexShader, scene, methodChosen,
                      shippedShaderPath(scene.shading, ShaderStage::Vertex)),
            stagePath(fragmentArg, scene.fragmentShader, scene, methodChosen,
                      shippedShaderPath(scene.shading, ShaderStage::Fragment))};
}

QString readSizeOption(const QCommandLineParser &parser, const QCommandLineOption &option, int maxSide, QSize *size)
{
    if (!parser.isSet(option))
        return {};
    const auto parsed = parseSizeArgument(parser.value(option), 1, maxSide);
    if (!parsed)
        return QStringLiteral("--size: expected WxH with 1..%1 pixels per side, got '%2'")
            .arg(maxSide)
            .arg(parser.value(option));
    *size = *parsed;
    return {};
}

QString readShadingOption(const QCommandLineParser &parser, const QCommandLineOption &option,
                          std::optional<ShadingMethod> *shading)
{
    if (!parser.isSet(option))
        return {};
    *shading = shadingFromName(parser.value(option));
    if (!*shading)
        return QStringLiteral("--shading: unknown method '%1' (known: %2)")
            .arg(parser.value(option), shadingNames().join(QStringLiteral(", ")));
    return {};
}

BuildReport buildStages(Renderer &renderer, const StageFiles &files, QString *error,
                        std::vector<ShaderStageText> *texts)
{
    const ShaderSource vs = ShaderSource::fromFile(files.vertex, error);
    const ShaderSource fs = ShaderSource::fromFile(files.fragment, error);
    if (!error->isEmpty())
        return {};
    if (texts) {
        texts->push_back({vs.name, QString::fromUtf8(vs.code), true});
        texts->push_back({fs.name, QString::fromUtf8(fs.code), false});
    }
    return renderer.setProgramSources(vs, fs);
}

bool writePng(const QImage &image, const QString &path, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        *error = QStringLiteral("%1: cannot write: %2").arg(path, file.errorString());
        return false;
    }
    if (!image.save(&file, "PNG")) {
        file.cancelWriting();
        *error = QStringLiteral("%1: PNG encoding failed").arg(path);
        return false;
    }
    if (!file.commit()) {
        *error = QStringLiteral("%1: cannot write: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace phonglab::cli
