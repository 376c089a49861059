#include "BenchCommand.h"
#include "core/support/AtomicFile.h"
#include "core/support/Language.h"

#include "BenchArgs.h"
#include "bench/BenchEngine.h"
#include "bench/BenchTable.h"
#include "bench/PathBench.h"
#include "charts/NormalStudyOutput.h"
#include "charts/PathChart.h"
#include "charts/SpeedAccuracyChart.h"
#include "cli/common/CliCommon.h"
#include "cli/common/ProgressLine.h"
#include "core/scene/ResourcePaths.h"

#include <QApplication>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>

#include <cstdio>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct BenchCommandWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::BenchCommand)
};

namespace {

// Progress on stderr, a line per step off a terminal (logs, and the
// Performance dock, which reads them); each finished row on stdout.
class ProgressPrinter
{
public:
    bool operator()(const BenchProgress &p)
    {
        m_line.show(QStringLiteral("[%1/%2] %3").arg(p.done).arg(p.total).arg(p.stage));
        if (!p.rows.empty()) {
            m_line.clear();
            for (const BenchRow &row : p.rows)
                printLine(benchTableLine(row));
            std::fflush(stdout);
        }
        return true;
    }
    void finish() { m_line.clear(); }

private:
    ProgressLine m_line{ProgressLine::Elsewhere::Lines};
};

int writeOutputs(const BenchArgs &args, const std::vector<BenchRow> &rows, bool writeResults = true)
{
    const QDir out(args.outDir);
    if (writeResults) {
        if (const Result<> written = writeFileAtomically(
                out.filePath(QStringLiteral("results.csv")), benchRowsToCsv(rows).toUtf8());
            !written) {
            printError(written.error());
            return kExitFailure;
        }
    }
    const std::vector<SceneFit> fits = fitScenes(rows, args.budget);
    if (const Result<> written = writeFileAtomically(out.filePath(QStringLiteral("fit.csv")),
                                                     sceneFitsToCsv(fits, args.budget).toUtf8());
        !written) {
        printError(written.error());
        return kExitFailure;
    }
    printLine(BenchCommandWords::tr(
                  "\nfit to budget (%1, the scene's own lights, %2 px silhouette band left out):")
                  .arg(args.budget.describe())
                  .arg(args.options.bandPx));
    for (const SceneFit &f : fits)
        printLine(QStringLiteral("  %1: %2").arg(f.scene, f.fit.summary));

    const QString png = out.filePath(QStringLiteral("chart.png"));
    const QString svg = out.filePath(QStringLiteral("chart.svg"));
    if (const Result<> charts = writeSpeedAccuracyCharts(rows, png, svg); !charts) {
        printError(charts.error());
        return kExitFailure;
    }
    QStringList written{out.filePath(QStringLiteral("fit.csv")), png, svg};
    if (writeResults)
        written.prepend(out.filePath(QStringLiteral("results.csv")));
    printLine(QStringLiteral("\nwrote %1").arg(written.join(QStringLiteral(", "))));
    return kExitOk;
}

void printObjectFitHeading(const ErrorBudget &budget)
{
    printLine(BenchCommandWords::tr("\nper-object fit (%1; each object drawn alone for its time, "
                                    "its own pixels for its error):")
                  .arg(budget.describe()));
}

// --from: the rows of an earlier run, fitted and charted again.
int refit(const BenchArgs &args)
{
    QFile file(args.fromCsv);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        printError(
            BenchCommandWords::tr("%1: cannot read: %2").arg(args.fromCsv, file.errorString()));
        return kExitFailure;
    }
    const Result<std::vector<BenchRow>> read =
        benchRowsFromCsv(QString::fromUtf8(file.readAll()), args.fromCsv);
    if (!read) {
        printError(read.error());
        return kExitFailure;
    }
    const std::vector<BenchRow> &rows = *read;
    printLine(benchTableHeader());
    for (const BenchRow &row : rows)
        printLine(benchTableLine(row));
    const int written = writeOutputs(args, rows, false);
    const std::vector<SceneObjectFit> objectFits = fitObjectsByScene(rows, args.budget);
    if (!objectFits.empty())
        printObjectFitHeading(args.budget);
    for (const SceneObjectFit &f : objectFits)
        printLine(QStringLiteral("  %1: %2").arg(f.scene, f.fit.summary));
    if (!objectFits.empty())
        printLine(BenchCommandWords::tr("  (--from draws nothing: the choices are not drawn whole "
                                        "to confirm them)"));
    return written;
}

QString percentSaved(double part, double whole)
{
    if (whole <= 0.0)
        return QStringLiteral("0 %");
    return QStringLiteral("%1 %").arg(sentenceNumber(100.0 * (1.0 - part / whole), 'f', 1));
}

PathOptions pathOptionsFrom(const BenchArgs &args)
{
    PathOptions options;
    options.budget = args.budget;
    options.pathFrames = args.pathFrames;
    options.bandPx = args.options.bandPx;
    options.imageDir = args.options.imageDir;
    if (args.sizeGiven)
        options.size = args.options.size;
    if (args.framesGiven)
        options.frames = args.options.frames;
    return options;
}

void printPathHeading(const BenchArgs &args, const PathOptions &options,
                      const QString &glRendererName)
{
    printLine(BenchCommandWords::tr(
                  "phonglab bench --path %1: %2 scene(s), %3x%4 px, %5 timed frames per "
                  "path frame, budget %6, GL: %7")
                  .arg(args.path)
                  .arg(args.options.scenes.size())
                  .arg(options.size.width())
                  .arg(options.size.height())
                  .arg(options.frames)
                  .arg(args.budget.describe(), glRendererName));
    printLine(
        BenchCommandWords::tr("every object at \"detail\": \"auto\" (%1 px, shading within %2 "
                              "steps), lights left out below %2 steps; against the exact Phong "
                              "image and the same frame at full detail with every light\n")
            .arg(options.detailPixels)
            .arg(sentenceNumber(255.0 * args.budget.reductionAllowance(), 'g', 3)));
}

void printPathFrame(const QString &scene, int done, int total, const PathFrame &f)
{
    printLine(BenchCommandWords::tr("  %1 frame %2/%3: distance %4, levels %5, %6 triangles "
                                    "(full %7), %8 lights left out, max error %9/255%10 "
                                    "(full detail %13/255), %11 ms (full %12 ms)")
                  .arg(QFileInfo(scene).completeBaseName())
                  .arg(done)
                  .arg(total)
                  .arg(sentenceNumber(f.distance, 'f', 2))
                  .arg(f.levels)
                  .arg(f.triangles)
                  .arg(f.fullTriangles)
                  .arg(f.lightsLeftOut)
                  .arg(f.maxError)
                  .arg(f.overBudget ? QStringLiteral(" OVER BUDGET") : QString())
                  .arg(sentenceNumber(f.frameMs, 'f', 2))
                  .arg(sentenceNumber(f.fullFrameMs, 'f', 2))
                  .arg(f.fullMaxError));
    std::fflush(stdout);
}

void printPathRun(const PathRun &run)
{
    printLine(BenchCommandWords::tr("%1, %2: %3 of %4 frames over budget (at full detail: %7); "
                                    "triangles %5 saved, time %6 saved against full detail")
                  .arg(run.scene, run.path)
                  .arg(run.overBudget())
                  .arg(run.frames.size())
                  .arg(percentSaved(double(run.triangles()), double(run.fullTriangles())),
                       percentSaved(run.frameMs(), run.fullFrameMs()))
                  .arg(run.fullOverBudget()));
}

// Every scene's path runs summed.
struct PathTotals {
    int over = 0, frames = 0, fullOver = 0;
    qint64 triangles = 0, fullTriangles = 0;
    double ms = 0, fullMs = 0;
};

PathTotals sumPathRuns(const std::vector<PathRun> &runs)
{
    PathTotals t;
    for (const PathRun &run : runs) {
        t.over += run.overBudget();
        t.fullOver += run.fullOverBudget();
        t.frames += int(run.frames.size());
        t.triangles += run.triangles();
        t.fullTriangles += run.fullTriangles();
        t.ms += run.frameMs();
        t.fullMs += run.fullFrameMs();
    }
    return t;
}

void printPathTotals(const PathTotals &t)
{
    printLine(
        QStringLiteral(
            "\nframes over budget: %1 of %2") /* scripts read it: never translated */.arg(t.over)
            .arg(t.frames));
    printLine(
        BenchCommandWords::tr("over budget at full detail with every light: %1 of %2 (what the "
                              "method itself misses; no model can do better there)")
            .arg(t.fullOver)
            .arg(t.frames));
    printLine(BenchCommandWords::tr(
                  "triangles drawn: %1 against %2 at full detail (%3 saved); frame time: "
                  "%4 ms against %5 ms (%6 saved), summed over the frames")
                  .arg(t.triangles)
                  .arg(t.fullTriangles)
                  .arg(percentSaved(double(t.triangles), double(t.fullTriangles)))
                  .arg(sentenceNumber(t.ms, 'f', 1))
                  .arg(sentenceNumber(t.fullMs, 'f', 1))
                  .arg(percentSaved(t.ms, t.fullMs)));
}

// path.csv and the path charts; false (the error printed) when one cannot be written.
bool writePathOutputs(const BenchArgs &args, const std::vector<PathRun> &runs)
{
    const QDir out(args.outDir);
    const QString csv = out.filePath(QStringLiteral("path.csv"));
    const QString png = out.filePath(QStringLiteral("path.png"));
    const QString svg = out.filePath(QStringLiteral("path.svg"));
    if (const Result<> written = writeFileAtomically(csv, pathRunsToCsv(runs).toUtf8()); !written) {
        printError(written.error());
        return false;
    }
    if (const Result<> chart = writePathCharts(runs, args.budget, png, svg); !chart) {
        printError(chart.error());
        return false;
    }
    printLine(QStringLiteral("wrote %1, %2, %3").arg(csv, png, svg));
    return true;
}

// --path: every scene along the camera path; the one line scripts read is
// "frames over budget: K of N" over all of them.
int benchPath(const BenchArgs &args)
{
    const PathOptions options = pathOptionsFrom(args);
    PathBench bench;
    if (const Result<> initialized = bench.initialize(); !initialized) {
        printError(initialized.error());
        return kExitFailure;
    }
    printPathHeading(args, options, bench.glRendererName());
    QElapsedTimer clock;
    clock.start();
    std::vector<PathRun> runs;
    for (const QString &scene : args.options.scenes) {
        const auto progress = [&](int done, int total, const PathFrame &f) {
            printPathFrame(scene, done, total, f);
            return true;
        };
        Result<PathRun> run = bench.run(scene, args.path, options, progress);
        if (!run) {
            printError(run.error());
            return kExitFailure;
        }
        printPathRun(*run);
        runs.push_back(std::move(*run));
    }
    printPathTotals(sumPathRuns(runs));
    if (!writePathOutputs(args, runs))
        return kExitFailure;
    printLine(BenchCommandWords::tr("done in %1 s")
                  .arg(sentenceNumber(clock.elapsed() / 1000.0, 'f', 1)));
    return kExitOk;
}

void printBenchHeading(const BenchArgs &args, const QString &glRendererName)
{
    printLine(
        BenchCommandWords::tr(
            "phonglab bench%1: %2 scene(s), %3x%4 px, %5 timed frames after %6 warm-up, GL: %7")
            .arg(args.quick ? QStringLiteral(" --quick") : QString())
            .arg(args.options.scenes.size())
            .arg(args.options.size.width())
            .arg(args.options.size.height())
            .arg(args.options.frames)
            .arg(args.options.warmupFrames)
            .arg(glRendererName));
    printLine(BenchCommandWords::tr(
        "frame ms = median wall time of render + glFinish; cpu ms = submission; "
        "errors in 8-bit steps against the CPU reference; hl = inside the specular "
        "highlight; * = the scene's own lights; blinn-phong uses the matched exponent 4n\n"));
    printLine(benchTableHeader());
}

// Each scene's per-object fit, and how its choices measured when drawn whole.
void printObjectFitChecks(const std::vector<ObjectFitCheck> &checks, const ErrorBudget &budget)
{
    if (!checks.empty())
        printObjectFitHeading(budget);
    for (const ObjectFitCheck &check : checks) {
        printLine(QStringLiteral("  %1: %2").arg(check.scene, check.fit.summary));
        if (check.measured)
            printLine(BenchCommandWords::tr("  %1: drawn whole: %2 ms, max %3/255, PSNR %4 dB (%5)")
                          .arg(check.scene)
                          .arg(sentenceNumber(check.measured->frameMs, 'f', 2))
                          .arg(check.measured->maxError)
                          .arg(sentenceNumber(check.measured->psnr, 'f', 1))
                          .arg(budget.accepts(*check.measured)
                                   ? BenchCommandWords::tr("within budget")
                                   : QStringLiteral("OVER BUDGET")));
    }
}

int bench(const BenchArgs &args)
{
    if (!QDir().mkpath(args.outDir)) {
        printError(BenchCommandWords::tr("%1: cannot create the output folder").arg(args.outDir));
        return kExitFailure;
    }
    if (!args.fromCsv.isEmpty())
        return refit(args);
    if (!args.path.isEmpty())
        return benchPath(args);
    BenchEngine engine;
    if (const Result<> initialized = engine.initialize(); !initialized) {
        printError(initialized.error());
        return kExitFailure;
    }
    printBenchHeading(args, engine.glRendererName());
    QElapsedTimer clock;
    clock.start();
    std::vector<BenchRow> rows;
    ProgressPrinter printer;
    BenchOptions options = args.options;
    options.objectFitBudget = args.budget;
    const Result<> ran = engine.run(options, &rows, std::ref(printer));
    printer.finish();
    if (!ran) {
        printError(ran.error());
        return kExitFailure;
    }
    if (args.normalStudy) {
        if (const Result<> study = writeNormalStudy(args.outDir); !study) {
            printError(study.error());
            return kExitFailure;
        }
    }
    const int written = writeOutputs(args, rows);
    printObjectFitChecks(engine.objectFits(), args.budget);
    printLine(BenchCommandWords::tr("done in %1 s")
                  .arg(sentenceNumber(clock.elapsed() / 1000.0, 'f', 1)));
    return written;
}

} // namespace

std::unique_ptr<QCoreApplication> makeWidgetsApplication(int &argc, char **argv)
{
    return std::make_unique<QApplication>(argc, argv);
}

int runBench(int argc, char **argv)
{
    const QStringList arguments = argumentsFrom(argc, argv).mid(1);
    const auto parsed = parseBenchArgs(arguments);
    if (const int *code = std::get_if<int>(&parsed))
        return *code;
    return bench(std::get<BenchArgs>(parsed));
}

} // namespace phonglab::cli
