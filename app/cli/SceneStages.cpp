#include "SceneStages.h"

#include "CliCommon.h"
#include "core/ResourcePaths.h"
#include "render/ShaderSource.h"

#include <QSaveFile>

namespace phonglab::cli {

namespace {

QString stagePath(const QString &fromArgs, const QString &fromScene, const Scene &scene,
                  bool methodChosen, const QString &shipped)
{
    if (!fromArgs.isEmpty())
        return fromArgs;
    if (!fromScene.isEmpty() && !methodChosen)
        return scene.resolveShaderPath(fromScene);
    return shipped;
}

} // namespace

StageFiles chooseStageFiles(const Scene &scene, const QString &vertexArg,
                            const QString &fragmentArg, bool methodChosen)
{
    return {stagePath(vertexArg, scene.vertexShader, scene, methodChosen,
                      shippedShaderPath(scene.shading, ShaderStage::Vertex)),
            stagePath(fragmentArg, scene.fragmentShader, scene, methodChosen,
                      shippedShaderPath(scene.shading, ShaderStage::Fragment))};
}

QString readSizeOption(const QCommandLineParser &parser, const QCommandLineOption &option,
                       int maxSide, QSize *size)
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

Result<BuildReport> buildStages(Renderer &renderer, const StageFiles &files,
                                std::vector<ShaderStageText> *texts)
{
    const Result<StageSources> read = readStageFiles(files.vertex, files.fragment);
    if (!read)
        return fail(read.error());
    const StageSources &stages = *read;
    if (texts) {
        texts->push_back({stages.vertex.name, QString::fromUtf8(stages.vertex.code), true});
        texts->push_back({stages.fragment.name, QString::fromUtf8(stages.fragment.code), false});
    }
    return renderer.setProgramSources(stages.vertex, stages.fragment);
}

Result<> writePng(const QImage &image, const QString &path)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fail(QStringLiteral("%1: cannot write: %2").arg(path, file.errorString()));
    if (!image.save(&file, "PNG")) {
        file.cancelWriting();
        return fail(QStringLiteral("%1: PNG encoding failed").arg(path));
    }
    if (!file.commit())
        return fail(QStringLiteral("%1: cannot write: %2").arg(path, file.errorString()));
    return {};
}

} // namespace phonglab::cli
