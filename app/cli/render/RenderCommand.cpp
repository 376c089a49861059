#include "RenderCommand.h"

#include "cli/common/CliCommon.h"
#include "cli/common/PngFiles.h"
#include "cli/common/SceneOverrides.h"
#include "cli/common/StageOptions.h"
#include "core/scene/ResourcePaths.h"
#include "core/scene/SceneJson.h"
#include "core/scene/ShadingMethod.h"
#include "render/draw/OffscreenRenderer.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QSurfaceFormat>

#include <optional>
#include <variant>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct RenderCommandWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::RenderCommand)
};

namespace {

struct RenderArgs {
    QString scenePath;
    QString outputPath;
    QSize size{800, 600};
    QString vertexPath;
    QString fragmentPath;
    std::optional<ShadingMethod> shading; // overrides the scene's
    SceneOverrides overrides;             // --bind, --define, --precision over the scene's
};

// Returns the arguments, or an exit code for usage errors / --help.
std::variant<RenderArgs, int> parseArgs(const QStringList &arguments)
{
    QCommandLineParser parser;
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  RenderCommandWords::tr("Show help."));
    parser.addPositionalArgument(QStringLiteral("scene"),
                                 RenderCommandWords::tr("Scene file (JSON)."));
    const QCommandLineOption output({QStringLiteral("o"), QStringLiteral("output")}, QString(),
                                    QStringLiteral("file"));
    const StageOptions stage;
    const SceneOverrideOptions overrides(SceneOverrideOptions::Use::Draw);

    const QString synopsis = RenderCommandWords::tr(
        "usage: phonglab render SCENE.json -o OUT.png [--size WxH] [--shading NAME] "
        "[--vertex FILE] [--fragment FILE] [--bind NAME=MEANING ...]\n"
        "                       [--define NAME=VALUE ...] [--precision highp|as-written]");
    //: %1: the lines of --size, --shading, --vertex, --fragment, --bind, --define and
    //: --precision, each option's own
    const QString helpText = synopsis
        + RenderCommandWords::tr(
              "\n\n"
              "Renders one frame of SCENE.json offscreen (no multisampling) into an 8-bit RGB "
              "PNG.\n\n"
              "  -o, --output FILE   the PNG to write (only written when everything succeeded)\n"
              "%1\n\n"
              "Exit status: 0 success, 1 bad input or compile/render failure, 2 wrong arguments.\n"
              "Compile errors are printed as FILE:LINE:COL: error: MESSAGE.")
              .arg(helpLines(
                  QList<QCommandLineOption>{stage.size, stage.shading, stage.vertex, stage.fragment}
                  + overrides.all()));
    const auto usage = [&](const QString &message) { return usageError(message, synopsis); };
    if (const std::optional<int> exit =
            parseOrExit(parser, arguments,
                        {help, QList<QCommandLineOption>{output} + stage.all() + overrides.all(),
                         SceneOverrideOptions::repeatable()},
                        synopsis, helpText))
        return *exit;
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1)
        return usage(positional.isEmpty()
                         ? RenderCommandWords::tr("missing the scene file")
                         : RenderCommandWords::tr("exactly one scene file expected"));
    if (!parser.isSet(output) || parser.value(output).isEmpty())
        return usage(RenderCommandWords::tr("missing -o OUT.png"));

    RenderArgs args;
    args.scenePath = positional.first();
    args.outputPath = parser.value(output);
    if (const QString problem = pngNameProblem(QStringLiteral("-o"), args.outputPath);
        !problem.isEmpty())
        return usage(problem);
    for (const QString &wrong : {readSizeOption(parser, stage.size, kMaxRenderedSide, &args.size),
                                 readShadingOption(parser, stage.shading, &args.shading),
                                 readSceneOverrides(parser, overrides, &args.overrides)})
        if (!wrong.isEmpty())
            return usage(wrong);
    args.vertexPath = parser.value(stage.vertex);
    args.fragmentPath = parser.value(stage.fragment);
    return args;
}

Result<BuildReport> buildProgram(Renderer &renderer, const RenderArgs &args, const Scene &scene)
{
    Scene chosen = scene;
    chosen.shading = args.shading.value_or(scene.shading);
    return buildStages(
        renderer,
        chooseStageFiles(chosen, args.vertexPath, args.fragmentPath, args.shading.has_value()));
}

int render(const RenderArgs &args)
{
    const SceneLoadResult loaded = loadSceneFile(args.scenePath);
    if (!loaded.ok()) {
        printError(QStringLiteral("%1: %2").arg(args.scenePath, loaded.error));
        return kExitFailure;
    }
    for (const QString &w : loaded.warnings)
        printErrLine(QStringLiteral("phonglab: warning: %1: %2").arg(args.scenePath, w));

    Scene scene = *loaded.scene;
    args.overrides.applyTo(scene);

    OffscreenRenderer offscreen;
    if (const Result<> created = offscreen.create(); !created) {
        printError(created.error());
        return kExitFailure;
    }
    Renderer &renderer = offscreen.renderer();
    if (const Result<> set = renderer.setScene(scene); !set) {
        printError(set.error());
        return kExitFailure;
    }
    const Result<BuildReport> built = buildProgram(renderer, args, scene);
    if (!built) {
        printError(built.error());
        return kExitFailure;
    }
    const BuildReport &program = *built;
    for (const ShaderDiagnostic &d : program.diagnostics)
        printErrLine(d.format());
    if (!program.ok) {
        printError(RenderCommandWords::tr("the shaders did not compile; no image written"));
        return kExitFailure;
    }
    for (const QString &problem : renderer.program().bindings().problems) {
        printError(QStringLiteral("--bind %1").arg(problem));
        return kExitFailure;
    }
    for (const UnboundUniform &unbound : unboundUniforms(renderer.program(), scene))
        printErrLine(QStringLiteral("phonglab: warning: %1").arg(unboundMessage(unbound)));
    const QImage image = offscreen.renderImage(args.size);
    if (image.isNull()) {
        printError(RenderCommandWords::tr("rendering failed"));
        return kExitFailure;
    }
    if (const std::optional<QString> depth = depthPrecisionWarning(renderer.depthRange()))
        printErrLine(QStringLiteral("phonglab: warning: %1: %2").arg(args.scenePath, *depth));
    if (const Result<> written = writePng(image, args.outputPath); !written) {
        printError(QStringLiteral("%1: %2").arg(args.outputPath, written.error()));
        return kExitFailure;
    }
    return kExitOk;
}

} // namespace

int runRender(int argc, char **argv)
{
    // argv[0] is the program, argv[1] "render": the parser sees "render" as the program name.
    const QStringList arguments = argumentsFrom(argc, argv).mid(1);
    const auto parsed = parseArgs(arguments);
    if (const int *code = std::get_if<int>(&parsed))
        return *code;
    return render(std::get<RenderArgs>(parsed));
}

} // namespace phonglab::cli
