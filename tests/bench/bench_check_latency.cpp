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
#include "BenchHelpers.h"
#include "core/ResourcePaths.h"
#include "core/SceneJson.h"
#include "ui/check/LiveCheck.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/window/MainWindow.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/shaders/ShaderFileSet.h"
#include "ui/viewport/Viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>
#include <algorithm>
#include <cmath>
#include <cstdio>

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
    parser.process(app);
    const int edits = std::max(1, parser.value(QStringLiteral("edits")).toInt());

    MainWindow window;
    window.resize(parser.value(QStringLiteral("width")).toInt(),
                  parser.value(QStringLiteral("height")).toInt());
    window.show();
    QString error;
    if (const Result<> done = window.openScene(defaultScenePath()); !done) {
        std::fprintf(stderr, "%s\n", qPrintable(done.error()));
        return 1;
    }
    Viewport *viewport = window.viewport();
    if (!QTest::qWaitFor(
            [&] { return viewport->isRenderReady() && viewport->framesRendered() > 0; }, 60000)) {
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
    QDir(ShaderFileSet::userFolder()).removeRecursively();
    return 0;
}
