#include "CheckCommand.h"

#include "CheckSteps.h"
#include "GradedChild.h"
#include "cli/common/CliCommon.h"
#include "cli/common/PngFiles.h"
#include "cli/common/SceneOverrides.h"
#include "cli/common/StageOptions.h"
#include "cli/page/PageOptions.h"
#include "cli/page/PageReport.h"
#include "core/project/ProjectPrograms.h"
#include "core/scene/SceneJson.h"
#include "render/check/CheckReportOutput.h"
#include "render/gl/QtImages.h"
#include "render/page/PageCheckOutput.h"

#include <QFileInfo>

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QJsonDocument>
#include <QTemporaryDir>

#include <optional>
#include <variant>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct CheckCommandWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::CheckCommand)
};

namespace {

struct CheckArgs {
    QString scenePath;
    QSize size{800, 600};
    QString vertexPath;
    QString fragmentPath;
    std::optional<ShadingMethod> shading;
    int toleranceSteps = kDefaultCheckToleranceSteps;
    bool json = false;
    QString diffPath;
    SceneOverrides overrides; // --bind, --define, --precision over the scene's
    std::optional<PhongEquation> equation;
    QString drawOnlyPath; // the hidden --draw-only OUT.png of grade's child
    QString projectPath;  // --project: a WebGL project's page, script or folder
    QString programName;  // --program: which of its programs
    PageRequest page;     // --page or --capture: the page as the browser ran it
};

const QString &synopsis()
{
    static const QString text = CheckCommandWords::tr(
        "usage: phonglab check SCENE.json [--vertex FILE] [--fragment FILE] "
        "[--shading NAME] [--size WxH]\n"
        "                      [--project PATH [--program NAME]]\n"
        "                      [--tolerance STEPS] [--bind NAME=MEANING ...] "
        "[--equation slide|guarded]\n"
        "                      [--define NAME=VALUE ...] "
        "[--precision highp|as-written]\n"
        "                      [--json] [--diff OUT.png]\n"
        "       phonglab check [SCENE.json] --page PROJECT [--page-file FILE] "
        "[--library DIR ...]\n"
        "                      [--url-map PREFIX=PATH ...] [--page-step STEP "
        "...] [--page-frame N]\n"
        "                      [--page-timeout S] [--meshes DIR] "
        "[--page-out DIR] [--json]\n"
        "       phonglab check [SCENE.json] --capture capture.json [--meshes "
        "DIR] [--json]");
    return text;
}

QString helpText(const StageOptions &stage, const SceneOverrideOptions &overrides)
{
    //: %1: the lines of --vertex and --fragment; %2: of --shading and --size; %4: of --bind,
    //: --define and --precision, each option's own
    return synopsis()
        + CheckCommandWords::tr(
              "\n\n"
              "Renders SCENE.json with the shaders `render` would use, compares the image with the "
              "exact\n"
              "(double-precision) reference of the same scene, leaving out a band around "
              "silhouettes,\n"
              "and when it differs names the classic mistake that explains it.\n\n"
              "%1\n"
              "  --project PATH      a WebGL project (a page, a script or a folder): its shaders "
              "are found in\n"
              "                      script elements, textareas, JavaScript strings or files of "
              "their own,\n"
              "                      and paired as its calls pair them\n"
              "  --program NAME      which of the project's programs, where it has several that "
              "light\n"
              "%2\n"
              "  --tolerance STEPS   largest error allowed per channel, in 8-bit steps (0..255), "
              "default %3\n"
              "%4\n"
              "  --equation E        demand the slide's equation (slide: a highlight even where "
              "N·L <= 0)\n"
              "                      or the guarded one (guarded: none there); by default "
              "either passes\n"
              "  --json              print one JSON object (keys: verdict, psnr_db, max_error, "
              "bad_fraction,\n"
              "                      tolerance, worst, diagnosis, undetectable, errors, "
              "bindings, equation,\n"
              "                      notes, warnings, together, partial, bindings_by_use, "
              "precision)\n"
              "                      instead of text\n"
              "  --diff OUT.png      write the error heatmap: dark green exact, bright green "
              "1/255, yellow 4/255,\n"
              "                      red 8/255 or more off; dark blue the silhouette band left "
              "out, black the\n"
              "                      background\n\n"
              "Mistake keys: %5, unknown.\n\n"
              "Exit status: 0 matches, 1 does not match, does not compile, or bad input, 2 wrong "
              "arguments.\n"
              "Compile errors are printed as FILE:LINE:COL: error: MESSAGE.")
              .arg(helpLines({stage.vertex, stage.fragment}),
                   helpLines({stage.shading, stage.size}),
                   QString::number(kDefaultCheckToleranceSteps), helpLines(overrides.all()),
                   shaderMistakeKeys().join(QStringLiteral(", ")))
        + pageOptionsHelp(PageOptions());
}

// The arguments, or an exit code for usage errors and --help.
// Every option of `check`, declared once.
struct CheckOptionSet {
    QCommandLineOption help{{QStringLiteral("h"), QStringLiteral("help")},
                            CheckCommandWords::tr("Show help.")};
    StageOptions stage;
    QCommandLineOption tolerance{QStringLiteral("tolerance"), QString(), QStringLiteral("steps")};
    QCommandLineOption json{QStringLiteral("json"), QString()};
    QCommandLineOption diff{QStringLiteral("diff"), QString(), QStringLiteral("file")};
    SceneOverrideOptions overrides{SceneOverrideOptions::Use::Check};
    QCommandLineOption equation{QStringLiteral("equation"), QString(), QStringLiteral("equation")};
    QCommandLineOption project{QStringLiteral("project"), QString(), QStringLiteral("path")};
    QCommandLineOption program{QStringLiteral("program"), QString(), QStringLiteral("name")};
    PageOptions page;
    QCommandLineOption drawOnly = hiddenOption(QStringLiteral("draw-only"), QStringLiteral("file"));

    // grade's child, not for people
    static QCommandLineOption hiddenOption(const QString &name, const QString &value)
    {
        QCommandLineOption option(name, QString(), value);
        option.setFlags(QCommandLineOption::HiddenFromHelp);
        return option;
    }
    QList<QCommandLineOption> valued() const
    {
        return stage.all()
            + QList<QCommandLineOption>{tolerance, json, diff, equation, drawOnly, project, program}
        + overrides.all() + page.all();
    }
};

// Each reader below fills its part of `args` from `parser` and returns the
// usage error of a wrong value, or an empty string.

// The scene file, or the page run instead of one.
QString readSceneOrPage(const QCommandLineParser &parser, const CheckOptionSet &o, CheckArgs &args)
{
    if (const QString wrong = readPageOptions(parser, o.page, &args.page); !wrong.isEmpty())
        return wrong;
    const QStringList positional = parser.positionalArguments();
    if (positional.size() > 1 || (positional.isEmpty() && !args.page.wanted))
        return positional.isEmpty() ? CheckCommandWords::tr("missing the scene file")
                                    : CheckCommandWords::tr("exactly one scene file expected");
    args.scenePath = positional.value(0);
    return {};
}

// How the frame is drawn and checked: --size, --shading, the scene's
// overrides, --equation and --tolerance.
QString readDrawingAndCheck(const QCommandLineParser &parser, const CheckOptionSet &o,
                            CheckArgs &args)
{
    for (const QString &wrong : {readSizeOption(parser, o.stage.size, kMaxCheckedSide, &args.size),
                                 readShadingOption(parser, o.stage.shading, &args.shading),
                                 readSceneOverrides(parser, o.overrides, &args.overrides)})
        if (!wrong.isEmpty())
            return wrong;
    if (parser.isSet(o.equation)) {
        args.equation = phongEquationFromKey(parser.value(o.equation));
        if (!args.equation)
            return CheckCommandWords::tr("--equation: expected slide or guarded, got '%1'")
                .arg(parser.value(o.equation));
    }
    if (parser.isSet(o.tolerance)) {
        bool ok = false;
        args.toleranceSteps = parser.value(o.tolerance).toInt(&ok);
        if (!ok || args.toleranceSteps < 0 || args.toleranceSteps > 255)
            return CheckCommandWords::tr("--tolerance: expected 0..255 8-bit steps, got '%1'")
                .arg(parser.value(o.tolerance));
    }
    return {};
}

// Where the shaders come from: --vertex and --fragment, --project and
// --program, or the page, one of them.
QString readShaderSources(const QCommandLineParser &parser, const CheckOptionSet &o,
                          CheckArgs &args)
{
    args.vertexPath = parser.value(o.stage.vertex);
    args.fragmentPath = parser.value(o.stage.fragment);
    args.projectPath = parser.value(o.project);
    args.programName = parser.value(o.program);
    const bool stageGiven = parser.isSet(o.stage.vertex) || parser.isSet(o.stage.fragment);
    if (args.page.wanted && !args.projectPath.isEmpty())
        return CheckCommandWords::tr("--project reads the shaders from the files, --page "
                                     "takes them from the browser: give one");
    if (args.page.wanted && stageGiven)
        return CheckCommandWords::tr("--page takes both stages from the browser; leave out "
                                     "--vertex and --fragment");
    if (!args.projectPath.isEmpty() && stageGiven)
        return CheckCommandWords::tr(
            "--project takes both stages from the project; leave out --vertex and --fragment");
    if (parser.isSet(o.program) && args.projectPath.isEmpty())
        return CheckCommandWords::tr("--program names a program of --project");
    return {};
}

// What is written: --json, --diff and grade's --draw-only.
QString readOutputs(const QCommandLineParser &parser, const CheckOptionSet &o, CheckArgs &args)
{
    if (parser.isSet(o.diff) && parser.value(o.diff).isEmpty())
        return CheckCommandWords::tr("--diff: missing the output file");
    args.json = parser.isSet(o.json);
    args.diffPath = parser.value(o.diff);
    args.drawOnlyPath = parser.value(o.drawOnly);
    return pngNameProblem(QStringLiteral("--diff"), args.diffPath);
}

std::variant<CheckArgs, int> parseArgs(const QStringList &arguments)
{
    QCommandLineParser parser;
    const CheckOptionSet o;
    parser.addPositionalArgument(QStringLiteral("scene"),
                                 CheckCommandWords::tr("Scene file (JSON)."));
    if (const std::optional<int> exit = parseOrExit(
            parser, arguments,
            {o.help, o.valued(), SceneOverrideOptions::repeatable() + PageOptions::repeatable()},
            synopsis(), helpText(o.stage, o.overrides)))
        return *exit;
    CheckArgs args;
    for (const auto read : {readSceneOrPage, readDrawingAndCheck, readShaderSources, readOutputs})
        if (const QString wrong = read(parser, o, args); !wrong.isEmpty())
            return usageError(wrong, synopsis());
    return args;
}

CheckInput inputOf(const CheckArgs &args)
{
    return {args.scenePath, args.vertexPath, args.fragmentPath, args.shading.has_value(),
            args.size};
}

// --project: the program's two stages as locators into the project's
// files, and what the project says beside (unlit programs left out). An
// error where no program can be chosen.
Result<QStringList> chooseProjectProgram(CheckArgs *args)
{
    const Project project = readProject(args->projectPath);
    const Result<ProjectProgram> choice = chooseProgram(project, args->programName);
    if (!choice)
        return fail(args->programName.isEmpty() && litPrograms(project).size() > 1
                        ? choice.error() + CheckCommandWords::tr(" with --program NAME")
                        : choice.error());
    const ProjectProgram *chosen = &*choice;
    args->vertexPath = shaderLocator(chosen->vertex);
    args->fragmentPath = shaderLocator(chosen->fragment);
    QStringList notes = project.notes;
    notes.prepend(
        CheckCommandWords::tr("program %1: %2 and %3")
            .arg(chosen->name,
                 QFileInfo(chosen->vertex.file).fileName() + QLatin1Char('#') + chosen->vertex.key,
                 QFileInfo(chosen->fragment.file).fileName() + QLatin1Char('#')
                     + chosen->fragment.key));
    return notes;
}

// Everything up to the verdict; `yours` receives the render for --diff.
CheckOutcome runCheckOn(CheckArgs args, const Scene &scene, CheckReference *reference,
                        QImage *yours)
{
    QStringList projectNotes;
    if (!args.projectPath.isEmpty()) {
        const Result<QStringList> chosen = chooseProjectProgram(&args);
        if (!chosen) {
            CheckOutcome failed;
            failed.errors.push_back(inputError(args.projectPath, chosen.error()));
            printErrLine(failed.errors.back().format());
            return failed;
        }
        projectNotes = *chosen;
    }
    CheckDrawing drawing = drawForCheck(inputOf(args), scene);
    drawing.findings.notes = projectNotes + drawing.findings.notes;
    for (const ShaderDiagnostic &d : drawing.compilerMessages)
        if (d.isError() || !args.json)
            printErrLine(d.format());
    const bool drawn = drawing.drawn();
    CheckOutcome outcome{std::move(drawing.findings)}; // Error until checked
    if (!drawn)
        return outcome;
    Result<CheckReference> made =
        makeCheckReference(sceneForCheck(scene, drawing.lightCapacity), drawing.objectMeshes,
                           args.size.width(), args.size.height());
    if (!made) {
        outcome.errors.push_back(inputError(
            args.scenePath, CheckCommandWords::tr("no reference: %1").arg(made.error())));
        return outcome;
    }
    *reference = std::move(*made);
    *yours = drawing.image;
    outcome.verdict = checkDrawing(&outcome, *yours, *reference, args.toleranceSteps, args.equation,
                                   args.scenePath);
    return outcome;
}

// The scene the check draws: the file's, with the command line's shading
// and bindings over it. Made once the application exists, so that its
// errors speak the run's language (core/support/Language).
SceneLoadResult checkedScene(const CheckArgs &args)
{
    SceneLoadResult loaded = loadSceneFile(args.scenePath);
    if (!loaded.ok())
        return loaded;
    if (args.shading)
        loaded.scene->shading = *args.shading;
    args.overrides.applyTo(*loaded.scene);
    return loaded;
}

// `grade`'s child: draws and hands the drawing back (stdout and a PNG); the
// parent checks it. Exit 0 whenever it could say what happened.
int drawOnly(const CheckArgs &args)
{
    beAGradedChild();
    injectGradedChildFault(args.fragmentPath);
    const SceneLoadResult loaded = checkedScene(args);
    if (!loaded.ok()) {
        CheckDrawing failed;
        failed.findings.errors.push_back(sceneError(args.scenePath, loaded));
        printLine(
            QString::fromUtf8(QJsonDocument(drawingJson(failed)).toJson(QJsonDocument::Compact)));
        return kExitOk;
    }
    CheckDrawing drawing = drawForCheck(inputOf(args), *loaded.scene);
    if (drawing.drawn()) {
        if (const Result<> written = writePng(drawing.image, args.drawOnlyPath); !written)
            drawing.findings.errors.push_back(inputError(args.drawOnlyPath, written.error()));
    }
    printLine(
        QString::fromUtf8(QJsonDocument(drawingJson(drawing)).toJson(QJsonDocument::Compact)));
    return kExitOk;
}

// The page `--page` or `--capture` names, checked before the scene.
struct PageStep {
    std::optional<PageCheck> page;
    QString note;
};

// Checks the page and, where it has a scene to check against, puts the
// page's shaders and constants in `args`. The exit code where the page is
// all there is to report.
std::optional<int> checkPageFirst(CheckArgs *args, const QTemporaryDir &compiled, PageStep *step)
{
    if (!args->scenePath.isEmpty())
        if (const SceneLoadResult scene = loadSceneFile(args->scenePath); scene.ok())
            takeScenePage(&args->page, scene.scene->page, scene.scene->baseDir);
    step->page = checkPage(args->page);
    const PageCheck &page = *step->page;
    if (const QString unwritten = writePageOutputs(page, args->page.outFolder);
        !unwritten.isEmpty())
        printError(unwritten);
    if (page.ok() && !args->scenePath.isEmpty()) {
        const PageStages stages =
            pageStagesForScene(page, args->page.run.folders.project, compiled.path());
        step->note = stages.note;
        args->vertexPath = stages.vertexPath;
        args->fragmentPath = stages.fragmentPath;
        for (const auto &[name, value] : stages.constants)
            if (!args->overrides.bindings.count(name))
                args->overrides.constants.emplace(name, value);
    }
    if (!page.ok() || args->scenePath.isEmpty() || args->vertexPath.isEmpty())
        return reportPageAlone(page, args->json, step->note);
    return std::nullopt;
}

// --diff: the heatmap of a checked render; a file that cannot be written
// turns the verdict into an error.
void writeDiff(CheckOutcome *outcome, const QImage &yours, const CheckReference &reference,
               const QString &diffPath)
{
    const Result<> written = writePng(
        toQImage(checkHeatmap(toRgbImage(yours), reference, outcome->report.equation)), diffPath);
    if (!written) {
        outcome->verdict = Verdict::Error;
        outcome->errors = {inputError(diffPath, written.error())};
        outcome->stages.clear();
    }
}

void printOutcome(const CheckOutcome &outcome, const std::optional<PageCheck> &page,
                  const Scene &scene, bool sceneLoaded, bool json)
{
    if (json) {
        QJsonObject out = checkJson(outcome.verdict, outcome);
        if (page)
            out.insert(QStringLiteral("page"), pageJson(*page));
        printLine(QString::fromUtf8(QJsonDocument(out).toJson(QJsonDocument::Indented)).trimmed());
        return;
    }
    if (page)
        for (const QString &line : pageText(*page))
            printLine(line);
    for (const ShaderDiagnostic &e : outcome.errors)
        // Compile errors with a line were printed as the compiler's; a
        // scene's syntax error has a line too, and its message says it.
        if (e.line == 0 || !sceneLoaded)
            printError(e.file.isEmpty() ? e.message
                                        : QStringLiteral("%1: %2").arg(e.file, e.message));
    printLine(checkText(outcome, scene));
}

int check(CheckArgs args)
{
    if (!args.drawOnlyPath.isEmpty())
        return drawOnly(args);
    PageStep page;
    const QTemporaryDir compiled;
    if (args.page.wanted)
        if (const std::optional<int> code = checkPageFirst(&args, compiled, &page))
            return *code;
    const SceneLoadResult loaded = checkedScene(args);
    const Scene scene = loaded.ok() ? *loaded.scene : Scene{};
    CheckOutcome outcome;
    CheckReference reference;
    QImage yours;
    if (!loaded.ok())
        outcome.errors.push_back(sceneError(args.scenePath, loaded));
    else
        outcome = runCheckOn(args, scene, &reference, &yours);
    // What the file says but is not checked as written, as render says it.
    outcome.warnings = loaded.warnings + outcome.warnings;
    for (const QString &w : loaded.warnings)
        printErrLine(QStringLiteral("phonglab: warning: %1: %2").arg(args.scenePath, w));

    if (outcome.verdict != Verdict::Error && !args.diffPath.isEmpty())
        writeDiff(&outcome, yours, reference, args.diffPath);
    if (page.page) {
        outcome.notes.prepend(page.note);
        if ((page.page->javascriptMistakes() || page.page->ownSceneFails())
            && outcome.verdict == Verdict::Pass)
            outcome.verdict = Verdict::Fail;
    }
    printOutcome(outcome, page.page, scene, loaded.ok(), args.json);
    return outcome.verdict == Verdict::Pass ? kExitOk : kExitFailure;
}

} // namespace

int runCheck(int argc, char **argv)
{
    const auto parsed = parseArgs(argumentsFrom(argc, argv).mid(1));
    if (const int *code = std::get_if<int>(&parsed))
        return *code;
    return check(std::get<CheckArgs>(parsed));
}

} // namespace phonglab::cli
