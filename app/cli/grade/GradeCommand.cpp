#include "GradeCommand.h"

#include "GradePages.h"

#include "ClassStaging.h"
#include "CoursePlatformOutputs.h"
#include "GradeReport.h"
#include "GradeRun.h"
#include "GradeTables.h"
#include "cli/common/CliCommon.h"
#include "cli/common/StageOptions.h"
#include "core/scene/SceneJson.h"
#include "core/support/AtomicFile.h"
#include "core/support/PhonglabExecutable.h"
#include "mesh/loading/MeshImportProcess.h"
#include "mesh/loading/SceneMeshes.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QTemporaryFile>
#include <QThread>

#include <cmath>
#include <map>
#include <variant>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct GradeCommandWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::GradeCommand)
};

namespace {

constexpr double kDefaultTimeoutS = 20.0;
constexpr int kDefaultMemoryMiB = 2048;

struct GradeArgs {
    GradeSettings settings;
    QStringList scenePaths;
    int jobs = 1;
    GradedChildLimits limits;
    GradePoints points;  // --points, for moodle-grades.csv
    bool resume = false; // --resume: the rows a stopped run finished are kept
    QString program;     // --program: only this program of each WebGL project
    PageRequest pages;   // --pages: each submission's page run in the browser
};

const QString &synopsis()
{
    static const QString text = GradeCommandWords::tr(
        "usage: phonglab grade SUBMISSIONS --scene FILE [--scene FILE ...] [--out DIR]\n"
        "                      [--jobs N] [--timeout SECONDS] [--memory MIB] [--size WxH]\n"
        "                      [--tolerance STEPS] [--bind NAME=MEANING ...] "
        "[--equation slide|guarded]\n"
        "                      [--define NAME=VALUE ...] [--precision highp|as-written]\n"
        "                      [--points pass=N,fail=N,error=N,timeout=N,crash=N] [--resume]\n"
        "                      [--program NAME]\n"
        "                      [--pages [--library DIR ...] [--url-map PREFIX=PATH ...] "
        "[--page-step STEP ...]\n"
        "                       [--page-frame N] [--page-timeout S] [--meshes DIR]]");
    return text;
}

QString helpText(const StageOptions &stage, const SceneOverrideOptions &overrides)
{
    //: %4: the line of --size; %6: of --bind, --define and --precision, each option's own
    return synopsis()
        + GradeCommandWords::tr(
              "\n\n"
              "Checks every submission in SUBMISSIONS against every scene, as `phonglab check` "
              "does,\n"
              "and writes what each student got into DIR. Each subfolder of SUBMISSIONS is one\n"
              "submission: its vertex and/or fragment shader, under any file names (.vert .vs "
              ".vsh,\n"
              ".frag .fs .fsh; .glsl by whether it writes gl_Position), in any dialect `check` "
              "takes,\n"
              "or a WebGL project (pages and scripts, as check --project reads them; each program\n"
              "that lights is checked on its own). SUBMISSIONS may be a .zip or .tar.gz, and a\n"
              "course platform's download: Moodle's folders or flat files by student. A student's\n"
              "own archive is unpacked once; an archive with links or names that leave it is\n"
              "refused. A stage left out is the scene's shading method's shipped one. Each check\n"
              "runs in a child process of its own: a shader that runs too long or crashes costs\n"
              "that one verdict.\n\n"
              "  --scene FILE        a scene to check with; repeatable, at least one\n"
              "  --out DIR           where the results go, default ./grades\n"
              "  --jobs N            checks at once, default the number of cores (%1)\n"
              "  --timeout SECONDS   wall-clock limit of one check, default %2\n"
              "  --memory MIB        memory limit of one check, default %3\n"
              "%4\n"
              "  --tolerance STEPS   largest error allowed per channel (0..255), default %5\n"
              "%6\n"
              "  --equation E        demand the slide's (slide) or the guarded (guarded) "
              "equation\n"
              "  --points P          what each verdict is worth in moodle-grades.csv, summed over "
              "a\n"
              "                      student's rows; default pass=1,fail=0,error=0,timeout=0,"
              "crash=0\n"
              "  --resume            keep the rows a stopped run of the same command finished\n"
              "  --program NAME      of a WebGL project with several programs, only this one\n\n"
              "Writes DIR/grades.csv (columns submission, scene, verdict, psnr_db, max_error,\n"
              "bad_fraction, key, also, file, line, equation, bindings, seconds, mistakes, "
              "program,\n"
              "student, participant, page_fidelity, page_javascript, page_error), DIR/grades.json\n"
              "(the check's JSON per row), DIR/report.html "
              "and its DIR/images/, and a table on stdout. From Moodle also DIR/moodle-grades.csv\n"
              "(its offline grading worksheet) and DIR/feedback.zip (a feedback.html per "
              "student).\n"
              "Verdicts: pass, fail, error, timeout, crash.\n\n"
              "Exit status: 0 every submission got a verdict, 1 the run could not complete (a "
              "scene\n"
              "that does not load, no submissions, DIR not writable), 2 wrong arguments.")
              .arg(QString::number(QThread::idealThreadCount()), QString::number(kDefaultTimeoutS),
                   QString::number(kDefaultMemoryMiB), helpLine(stage.size),
                   QString::number(kDefaultCheckToleranceSteps), helpLines(overrides.all()))
        + GradeCommandWords::tr("\n\nWith --pages each submission's page runs in headless "
                                "Chromium, as check --page runs it,\n"
                                "once per project (its capture and frames in DIR/pages/NAME/); "
                                "the course scenes are then\n"
                                "checked with the program and the values the page used.\n")
        + helpLines(PageOptions(PageOptions::Use::Grade).all());
}

// Every option of `grade`, declared once.
struct GradeOptionSet {
    QCommandLineOption help{{QStringLiteral("h"), QStringLiteral("help")},
                            GradeCommandWords::tr("Show help.")};
    QCommandLineOption scene{QStringLiteral("scene"), QString(), QStringLiteral("file")};
    QCommandLineOption out{QStringLiteral("out"), QString(), QStringLiteral("dir")};
    QCommandLineOption jobs{QStringLiteral("jobs"), QString(), QStringLiteral("n")};
    QCommandLineOption timeout{QStringLiteral("timeout"), QString(), QStringLiteral("s")};
    QCommandLineOption memory{QStringLiteral("memory"), QString(), QStringLiteral("mib")};
    StageOptions stage; // --size alone: each submission brings its own stages
    QCommandLineOption tolerance{QStringLiteral("tolerance"), QString(), QStringLiteral("steps")};
    SceneOverrideOptions overrides{SceneOverrideOptions::Use::Check};
    QCommandLineOption equation{QStringLiteral("equation"), QString(), QStringLiteral("equation")};
    QCommandLineOption points{QStringLiteral("points"), QString(), QStringLiteral("points")};
    QCommandLineOption resume{QStringLiteral("resume"), QString()};
    QCommandLineOption program{QStringLiteral("program"), QString(), QStringLiteral("name")};
    PageOptions pages{PageOptions::Use::Grade};

    QList<QCommandLineOption> valued() const
    {
        return QList<QCommandLineOption>{scene,     out,      jobs,   timeout, memory, stage.size,
                                         tolerance, equation, points, resume,  program}
        + overrides.all() + pages.all();
    }
};

// Each reader below fills its part of `args` from `parser` and returns the
// usage error of a wrong value, or an empty string.

// SUBMISSIONS, --scene and --out.
QString readClassAndScenes(const QCommandLineParser &parser, const GradeOptionSet &o,
                           GradeArgs &args)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1)
        return positional.isEmpty()
            ? GradeCommandWords::tr("missing the submissions folder")
            : GradeCommandWords::tr("exactly one submissions folder expected");
    GradeSettings &settings = args.settings;
    settings.classFolder = positional.first();
    args.scenePaths = parser.values(o.scene);
    if (args.scenePaths.isEmpty())
        return GradeCommandWords::tr("--scene: at least one scene expected");
    settings.outFolder = parser.isSet(o.out) ? parser.value(o.out) : QStringLiteral("grades");
    if (settings.outFolder.isEmpty())
        return GradeCommandWords::tr("--out: missing the folder");
    return {};
}

// How each row is checked: --size, --bind and the rest of the scene's
// overrides, the page's options, --equation, --points, --resume, --program
// and --tolerance.
QString readCheckSettings(const QCommandLineParser &parser, const GradeOptionSet &o,
                          GradeArgs &args)
{
    GradeSettings &settings = args.settings;
    for (const QString &wrong :
         {readSizeOption(parser, o.stage.size, kMaxCheckedSide, &settings.size),
          readSceneOverrides(parser, o.overrides, &settings.overrides),
          readPageOptions(parser, o.pages, &args.pages)})
        if (!wrong.isEmpty())
            return wrong;
    if (parser.isSet(o.equation)) {
        settings.equation = phongEquationFromKey(parser.value(o.equation));
        if (!settings.equation)
            return GradeCommandWords::tr("--equation: expected slide or guarded, got '%1'")
                .arg(parser.value(o.equation));
    }
    if (parser.isSet(o.points)) {
        const Result<GradePoints> parsed = parseGradePoints(parser.value(o.points));
        if (!parsed)
            return parsed.error();
        args.points = *parsed;
    }
    args.resume = parser.isSet(o.resume);
    args.program = parser.value(o.program);
    if (parser.isSet(o.tolerance)) {
        bool ok = false;
        settings.toleranceSteps = parser.value(o.tolerance).toInt(&ok);
        if (!ok || settings.toleranceSteps < 0 || settings.toleranceSteps > 255)
            return GradeCommandWords::tr("--tolerance: expected 0..255 8-bit steps, got '%1'")
                .arg(parser.value(o.tolerance));
    }
    return {};
}

// What the children may use: --jobs, --timeout and --memory.
QString readChildLimits(const QCommandLineParser &parser, const GradeOptionSet &o, GradeArgs &args)
{
    bool ok = true;
    args.jobs = QThread::idealThreadCount();
    if (parser.isSet(o.jobs)) {
        args.jobs = parser.value(o.jobs).toInt(&ok);
        if (!ok || args.jobs < 1 || args.jobs > 256)
            return GradeCommandWords::tr("--jobs: expected 1..256, got '%1'")
                .arg(parser.value(o.jobs));
    }
    const double seconds =
        parser.isSet(o.timeout) ? parser.value(o.timeout).toDouble(&ok) : kDefaultTimeoutS;
    if (!ok || !std::isfinite(seconds) || seconds <= 0 || seconds > 86400)
        return GradeCommandWords::tr("--timeout: expected seconds in (0, 86400], got '%1'")
            .arg(parser.value(o.timeout));
    args.limits.wallClockMs = int(std::lround(seconds * 1000));
    const qint64 mib =
        parser.isSet(o.memory) ? parser.value(o.memory).toLongLong(&ok) : qint64(kDefaultMemoryMiB);
    if (!ok || mib < 64 || mib > 1024 * 1024)
        return GradeCommandWords::tr("--memory: expected 64..1048576 MiB, got '%1'")
            .arg(parser.value(o.memory));
    args.limits.memoryBytes = mib * 1024 * 1024;
    return {};
}

std::variant<GradeArgs, int> parseArgs(const QStringList &arguments)
{
    QCommandLineParser parser;
    const GradeOptionSet o;
    parser.addPositionalArgument(QStringLiteral("submissions"), QString());
    if (const std::optional<int> exit =
            parseOrExit(parser, arguments,
                        {o.help, o.valued(),
                         QStringList{QStringLiteral("scene")} + SceneOverrideOptions::repeatable()
                             + PageOptions::repeatable()},
                        synopsis(), helpText(o.stage, o.overrides)))
        return *exit;
    GradeArgs args;
    for (const auto read : {readClassAndScenes, readCheckSettings, readChildLimits})
        if (const QString wrong = read(parser, o, args); !wrong.isEmpty())
            return usageError(wrong, synopsis());
    return args;
}

// Each scene loaded, with --bind applied, and its meshes for the exact image.
Result<std::vector<GradeScene>> loadScenes(const GradeArgs &args)
{
    std::vector<GradeScene> scenes;
    std::map<QString, int> names;
    for (const QString &path : args.scenePaths)
        ++names[QFileInfo(path).fileName()];
    for (const QString &path : args.scenePaths) {
        const SceneLoadResult loaded = loadSceneFile(path);
        if (!loaded.ok())
            return fail(QStringLiteral("%1: %2").arg(path, loaded.error));
        GradeScene s;
        s.path = path;
        s.label = names[QFileInfo(path).fileName()] > 1 ? path : QFileInfo(path).fileName();
        s.slug = QStringLiteral("%1-%2")
                     .arg(scenes.size() + 1)
                     .arg(fileSlug(QFileInfo(path).completeBaseName()));
        s.scene = *loaded.scene;
        args.settings.overrides.applyTo(s.scene);
        SceneMeshes meshes = loadSceneMeshes(s.scene);
        if (!meshes.ok())
            return fail(QStringLiteral("%1: %2").arg(path, meshes.error));
        for (const SceneObject &object : s.scene.objects)
            s.objectMeshes.push_back(meshes.entries.value(meshKey(s.scene, object)).mesh);
        scenes.push_back(std::move(s));
    }
    return scenes;
}

Result<> prepareOutFolder(const QString &folder)
{
    if (!QDir().mkpath(folder + QStringLiteral("/images")))
        return fail(GradeCommandWords::tr("%1: cannot make the folder").arg(folder));
    QTemporaryFile probe(folder + QStringLiteral("/.write-test-XXXXXX"));
    if (!probe.open())
        return fail(
            GradeCommandWords::tr("%1: cannot write into it: %2").arg(folder, probe.errorString()));
    return {};
}

Result<> writeOutputs(const GradeResults &results, const GradePoints &points)
{
    const QString dir = results.settings.outFolder + QLatin1Char('/');
    for (const Result<> &written :
         {writeFileAtomically(dir + QStringLiteral("grades.csv"), gradesCsv(results)),
          writeFileAtomically(dir + QStringLiteral("grades.json"),
                              QJsonDocument(gradesJson(results)).toJson(QJsonDocument::Indented)),
          writeFileAtomically(dir + QStringLiteral("report.html"),
                              gradeReportHtml(results).toUtf8())})
        if (!written)
            return written;
    // Back to Moodle, where the submissions came from it.
    if (const QByteArray moodle = moodleGradesCsv(results, points); !moodle.isEmpty())
        if (const Result<> written =
                writeFileAtomically(dir + QStringLiteral("moodle-grades.csv"), moodle);
            !written)
            return written;
    return writeFeedbackZip(results, dir + QStringLiteral("feedback.zip"));
}

// --program: of each WebGL project, only that program. A student whose
// project has no such program keeps a row that says so; shader files stay.
std::vector<Submission> onlyProgram(const std::vector<Submission> &all, const QString &program)
{
    std::vector<Submission> kept;
    for (std::size_t i = 0; i < all.size();) {
        std::size_t end = i;
        QStringList names;
        const Submission *match = nullptr;
        for (; end < all.size() && all[end].name == all[i].name; ++end) {
            names << all[end].program;
            if (all[end].program == program)
                match = &all[end];
        }
        if (all[i].program.isEmpty() || match) {
            kept.push_back(match ? *match : all[i]);
        } else {
            Submission missing = all[i];
            missing.error = GradeCommandWords::tr("no program named %1 (there are: %2)")
                                .arg(program, names.join(QStringLiteral(", ")));
            kept.push_back(std::move(missing));
        }
        i = end;
    }
    return kept;
}

// What makes two runs one: the scenes, the settings and every submission's
// files; a journal of another run is not resumed.
QByteArray runFingerprint(const GradeArgs &args, const GradeResults &results)
{
    QStringList parts{
        QString::number(args.settings.size.width()), QString::number(args.settings.size.height()),
        QString::number(args.settings.toleranceSteps),
        args.settings.equation ? phongEquationKey(*args.settings.equation) : QString()};
    parts << args.settings.overrides.arguments();
    for (const QString &scene : args.scenePaths)
        parts << QFileInfo(scene).absoluteFilePath();
    for (const Submission &s : results.submissions)
        parts << s.name << s.program << s.vertex << s.fragment << s.error;
    return QCryptographicHash::hash(parts.join(QLatin1Char('\x1f')).toUtf8(),
                                    QCryptographicHash::Sha256)
        .toHex();
}

// The class as submissions: an archive or Moodle's flat files become
// folders under the out folder first, and a refused archive is its
// student's error.
Result<> readSubmissions(const GradeArgs &args, GradeResults *results)
{
    const StagedClass staged = stageClass(args.settings.classFolder, args.settings.outFolder);
    if (!staged.error.isEmpty())
        return fail(staged.error);
    results->settings.classRoot = staged.root;
    const ClassFolder folder = readClassFolder(staged.root);
    if (!folder.error.isEmpty())
        return fail(folder.error);
    results->submissions =
        args.program.isEmpty() ? folder.submissions : onlyProgram(folder.submissions, args.program);
    for (Submission &s : results->submissions) {
        const SubmissionOrigin origin = staged.origins.value(s.name);
        s.student = origin.student;
        s.participant = origin.participant;
        if (staged.refused.contains(s.name)) // an archive of theirs was refused: that is the error
            s.error = staged.refused.value(s.name);
    }
    return {};
}

// --pages: each submission's page, with the first scene's "page", as the
// course states it.
void runPages(const GradeArgs &args, GradeResults &results)
{
    PageRequest pages = args.pages;
    if (!results.scenes.empty())
        takeScenePage(&pages, results.scenes.front().scene.page,
                      results.scenes.front().scene.baseDir);
    runSubmissionPages(results, pages, args.jobs);
}

// --resume: the checks the stopped run finished; else a new journal.
QHash<QString, GradedChildEnd> resumeOrStart(GradeJournal &journal, bool resume)
{
    QHash<QString, GradedChildEnd> finished;
    if (resume) {
        finished = journal.resume();
        printErrLine(GradeCommandWords::tr("grade: kept %1 finished checks of the stopped run")
                         .arg(finished.size()));
    } else
        journal.start();
    return finished;
}

int grade(const GradeArgs &args)
{
    GradeResults results;
    results.settings = args.settings;
    if (const Result<> read = readSubmissions(args, &results); !read) {
        printError(read.error());
        return kExitFailure;
    }
    Result<std::vector<GradeScene>> scenes = loadScenes(args);
    if (!scenes) {
        printError(scenes.error());
        return kExitFailure;
    }
    results.scenes = std::move(*scenes);
    if (const Result<> ready = prepareOutFolder(args.settings.outFolder); !ready) {
        printError(ready.error());
        return kExitFailure;
    }
    if (args.pages.wanted)
        runPages(args, results);
    const QString executable = phonglabExecutable();
    if (executable.isEmpty()) {
        printError(GradeCommandWords::tr("cannot find the phonglab program to run the checks with "
                                         "(set PHONGLAB_EXE)"));
        return kExitFailure;
    }
    GradeRun run(results, executable, args.jobs, args.limits);
    if (const Result<> prepared = run.prepareReferences(); !prepared) {
        printError(prepared.error());
        return kExitFailure;
    }
    GradeJournal journal(args.settings.outFolder, runFingerprint(args, results));
    run.setJournal(&journal, resumeOrStart(journal, args.resume));
    run.run();
    if (const Result<> written = writeOutputs(results, args.points); !written) {
        printError(written.error());
        return kExitFailure;
    }
    journal.finish();
    printLine(gradesTable(results));
    printErrLine(GradeCommandWords::tr("grade: %1 checks; %2")
                     .arg(QString::number(results.rows.size()),
                          QDir(args.settings.outFolder).filePath(QStringLiteral("report.html"))));
    return kExitOk;
}

} // namespace

int runGrade(int argc, char **argv)
{
    const auto parsed = parseArgs(argumentsFrom(argc, argv).mid(1));
    if (const int *code = std::get_if<int>(&parsed))
        return *code;
    return grade(std::get<GradeArgs>(parsed));
}

} // namespace phonglab::cli
