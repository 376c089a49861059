#include "StageOptions.h"

#include "CliCommon.h"
#include "core/scene/ResourcePaths.h"
#include "render/program/ShaderSource.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <algorithm>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct StageOptionsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::StageOptions)
};

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

StageOptions::StageOptions()
    : size(QStringLiteral("size"), StageOptionsWords::tr("image size in pixels, default 800x600"),
           QStringLiteral("WxH"))
    , vertex(QStringLiteral("vertex"),
             StageOptionsWords::tr("vertex shader instead of the scene's or the shading method's"),
             QStringLiteral("FILE"))
    , fragment(QStringLiteral("fragment"),
               StageOptionsWords::tr("fragment shader instead of the scene's or the shading "
                                     "method's"),
               QStringLiteral("FILE"))
    , shading(QStringLiteral("shading"),
              StageOptionsWords::tr("shading method instead of the scene's \"shading\"; one of\n%1")
                  .arg(shadingNames().join(QStringLiteral(", "))),
              QStringLiteral("NAME"))
{
}

QString readSizeOption(const QCommandLineParser &parser, const QCommandLineOption &option,
                       int maxSide, QSize *size)
{
    if (!parser.isSet(option))
        return {};
    const auto parsed = parseSizeArgument(parser.value(option), 1, maxSide);
    if (!parsed)
        return StageOptionsWords::tr("--size: expected WxH with 1..%1 pixels per side, got '%2'")
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
        return StageOptionsWords::tr("--shading: unknown method '%1' (known: %2)")
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

QString unboundMessage(const UnboundUniform &unbound)
{
    if (unbound.likely)
        return unboundSentence(unbound)
            + StageOptionsWords::tr(
                  "; if it is %1, add --bind %2=%3 (or \"bindings\" in the scene)")
                  .arg(bindingMeaningDescription(*unbound.likely), unbound.name,
                       bindingMeaningKey(*unbound.likely));
    return unboundSentence(unbound)
        + StageOptionsWords::tr("; bind it with --bind %1=MEANING (meanings: %2), or give it a "
                                "value in the scene's \"uniforms\"")
              .arg(unbound.name, bindingMeaningKeys().join(QStringLiteral(", ")));
}

} // namespace phonglab::cli
