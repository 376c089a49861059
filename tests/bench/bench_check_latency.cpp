// Compile-to-verdict latency of the editor's check (prints figures; not a test).
//
//   xvfb-run -a build/tests/bench/bench_check_latency [--edits N] [--width W --height H]
//
// The real window on the default scene. Each edit scales the Phong fragment
// shader's output by a new constant (a new text, a new program), starts the
// build as the debounce would, and measures from LiveShaderController::
// programApplied (the good compile is in the view) to LiveCheck::checked
// (the verdict is on screen). The first check of a view also makes the
// reference (ray-casting the scene), which later edits reuse: it is printed
// apart. The peer in the same run is one frame of the same view rendered
// again at the same size (Viewport::renderImage), so the ratio survives a
// noisy machine.
//
//   ... [--busy N]
//
// Then the first check of a new view (the window narrowed: a new exact image
// to make), idle and again with N programs busy beside the window (shell
// loops, 2 by default: a student's browser and build), in one run: the time
// to the verdict of each, their ratio, and the GUI thread's stalls while
// each check runs (gaps between 2 ms timer ticks).
#include "BenchHelpers.h"
#include "core/scene/ResourcePaths.h"
#include "core/scene/SceneJson.h"
#include "ui/check/LiveCheck.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/shaders/ShaderFileSet.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

using namespace phonglab;
using namespace phonglab::bench;

namespace {

// From a new fragment text to the verdict; -1 on a timeout.
struct Sample {
    double compileToVerdictMs = -1;
    double workerMs = -1; // the check's own time (request to result)
};

Sample edit(MainWindow &window, const QByteArray &text)
{
    QSignalSpy applied(window.liveShaders(), &LiveShaderController::programApplied);
    QSignalSpy checked(window.liveCheck(), &LiveCheck::checked);
    window.shaderDock()->editor(ShaderStage::Fragment)->setText(QString::fromUtf8(text));
    window.liveShaders()->buildNow();
    if (!QTest::qWaitFor([&] { return applied.count() > 0; }, 60000))
        return {};
    QElapsedTimer clock;
    clock.start();
    if (!QTest::qWaitFor([&] { return checked.count() > 0 && !window.liveCheck()->isChecking(); },
                         60000))
        return {};
    return {double(clock.nsecsElapsed()) / 1e6, window.liveCheck()->lastResult()->milliseconds};
}

// The first check of a new view: the window narrowed by `narrower` pixels,
// to the verdict of that size; the GUI thread's gaps meanwhile.
struct ViewSample {
    double verdictMs = -1;
    double stallP95Ms = 0;
    double stallMaxMs = 0;
};

ViewSample newView(MainWindow &window, int narrower)
{
    QSignalSpy checked(window.liveCheck(), &LiveCheck::checked);
    std::vector<double> gaps;
    QElapsedTimer tick;
    QTimer timer;
    timer.setInterval(2);
    QObject::connect(&timer, &QTimer::timeout, [&] {
        gaps.push_back(double(tick.nsecsElapsed()) / 1e6);
        tick.restart();
    });
    QElapsedTimer clock;
    clock.start();
    tick.start();
    timer.start();
    window.resize(window.width() - narrower, window.height());
    const bool done = QTest::qWaitFor(
        [&] {
            return checked.count() > 0 && !window.liveCheck()->isChecking()
                && window.liveCheck()->lastResult()->reference;
        },
        600000);
    timer.stop();
    if (!done)
        return {};
    return {double(clock.nsecsElapsed()) / 1e6, percentile(gaps, 0.95),
            *std::max_element(gaps.begin(), gaps.end())};
}

// Programs that keep a core busy until they are stopped (or 15 minutes
// pass, should this program die first).
std::vector<std::unique_ptr<QProcess>> busyPrograms(int n)
{
    std::vector<std::unique_ptr<QProcess>> out;
    for (int i = 0; i < n; ++i) {
        auto p = std::make_unique<QProcess>();
        p->start(QStringLiteral("timeout"),
                 {QStringLiteral("900"), QStringLiteral("sh"), QStringLiteral("-c"),
                  QStringLiteral("while :; do :; done")});
        p->waitForStarted();
        out.push_back(std::move(p));
    }
    return out;
}

} // namespace

int main(int argc, char **argv)
{
    QTemporaryDir recovery;
    qputenv("PHONGLAB_RECOVERY_DIR", recovery.path().toUtf8());
    qputenv("PHONGLAB_RECOVERY_ANSWER", "discard");
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    QCommandLineParser parser;
    parser.addHelpOption();
    parser.addOption({QStringLiteral("edits"), QStringLiteral("Edits (default 30)."),
                      QStringLiteral("N"), QStringLiteral("30")});
    parser.addOption({QStringLiteral("width"), QStringLiteral("Window width (default 1280)."),
                      QStringLiteral("W"), QStringLiteral("1280")});
    parser.addOption({QStringLiteral("height"), QStringLiteral("Window height (default 800)."),
                      QStringLiteral("H"), QStringLiteral("800")});
    parser.addOption({QStringLiteral("busy"),
                      QStringLiteral("Busy programs beside the window for the new-view check "
                                     "(default 2)."),
                      QStringLiteral("N"), QStringLiteral("2")});
    parser.process(app);
    const int edits = std::max(1, parser.value(QStringLiteral("edits")).toInt());

    MainWindow window;
    window.resize(parser.value(QStringLiteral("width")).toInt(),
                  parser.value(QStringLiteral("height")).toInt());
    window.show();
    QString error;
    if (const Result<> done = window.document()->openAndWait(defaultScenePath()); !done) {
        std::fprintf(stderr, "%s\n", qPrintable(done.error()));
        return 1;
    }
    Viewport *viewport = window.viewport();
    if (!QTest::qWaitFor(
            [&] {
                return viewport->isRenderReady() && viewport->frames().frameStats().rendered > 0;
            },
            60000)) {
        std::fprintf(stderr, "the view did not come up\n");
        return 1;
    }
    const QSize pixels = viewport->size() * viewport->devicePixelRatioF();
    const Sample cold = edit(window, editedFragment(0.99));
    std::vector<double> verdict, worker, frame;
    for (int i = 0; i < edits; ++i) {
        const Sample s = edit(window, editedFragment(0.98 - 0.0001 * i));
        if (s.compileToVerdictMs < 0) {
            std::fprintf(stderr, "edit %d: no verdict\n", i);
            return 1;
        }
        verdict.push_back(s.compileToVerdictMs);
        worker.push_back(s.workerMs);
        QElapsedTimer clock;
        clock.start();
        viewport->renderImage(pixels, false);
        frame.push_back(double(clock.nsecsElapsed()) / 1e6);
    }
    const double p50 = percentile(verdict, 0.5), p95 = percentile(verdict, 0.95),
                 f50 = percentile(frame, 0.5);
    std::printf("default scene, viewport %dx%d px, %d edits, %d CPUs\n", pixels.width(),
                pixels.height(), edits, QThread::idealThreadCount());
    std::printf("| measure | p50 ms | p95 ms |\n|---|---|---|\n");
    std::printf("| good compile -> verdict (reference kept) | %.0f | %.0f |\n", p50, p95);
    std::printf("| of which the check itself (worker) | %.0f | %.0f |\n", percentile(worker, 0.5),
                percentile(worker, 0.95));
    std::printf("| peer: one frame of the same view | %.0f | %.0f |\n", f50,
                percentile(frame, 0.95));
    std::printf("| first check of a view (makes the reference) | %.0f | |\n",
                cold.compileToVerdictMs);
    std::printf("verdict / frame at p50: %.1fx\n", p50 / std::max(f50, 1e-9));

    const int busy = std::max(0, parser.value(QStringLiteral("busy")).toInt());
    const ViewSample idle = newView(window, 16);
    ViewSample loaded;
    {
        const auto programs = busyPrograms(busy);
        loaded = newView(window, 16);
        // SIGTERM, which `timeout` hands on to its loop (a SIGKILL would
        // leave the loop running).
        for (const auto &p : programs)
            p->terminate();
        for (const auto &p : programs)
            p->waitForFinished();
    }
    if (idle.verdictMs < 0 || loaded.verdictMs < 0) {
        std::fprintf(stderr, "a new view got no verdict\n");
        return 1;
    }
    std::printf("\nfirst check of a new view (makes the exact image), idle and beside %d busy "
                "programs:\n",
                busy);
    std::printf(
        "| machine | verdict ms | GUI gap p95 ms | longest GUI gap ms |\n|---|---|---|---|\n");
    std::printf("| idle | %.0f | %.1f | %.1f |\n", idle.verdictMs, idle.stallP95Ms,
                idle.stallMaxMs);
    std::printf("| %d busy | %.0f | %.1f | %.1f |\n", busy, loaded.verdictMs, loaded.stallP95Ms,
                loaded.stallMaxMs);
    std::printf("busy / idle: %.2fx (aim: <= 5x)\n", loaded.verdictMs / idle.verdictMs);
    QDir(ShaderFileSet::userFolder()).removeRecursively();
    return 0;
}
