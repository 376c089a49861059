// Edit-to-pixel latency of live shader editing (prints figures; not a test).
//
//   xvfb-run -a build/tests/bench/bench_edit_latency [--edits N] [--samples S]
//
// Each edit changes a constant in the Phong fragment shader (so every text is
// new), starts the build and stops the clock when the viewport has finished
// (glFinish) its first frame with the new program. The app's path starts it
// as the debounce would (LiveShaderController::buildNow). The other PhongLab
// paths are the ways the app could build that it does not, kept here for the
// comparison: the worker warming the program in its own context, the worker
// without a warm-up, and compiling on the GUI thread; each adopts its program
// into the same window's viewport (no live check runs after those).
// Compared with a raw-GL path in the same process: glCreateShader/
// glCompileShader/glLinkProgram and one draw of the same mesh with the same
// uniforms, no Qt wrappers. While each edit runs, a
// 1 ms timer on the GUI thread records the longest gap between its ticks:
// how long typing would have frozen. Mesa's shader cache is disabled so that
// every build pays the full price, as a new text does.
#include "BenchHelpers.h"
#include "EditSample.h"
#include "RawGlEditPath.h"
#include "core/scene/ResourcePaths.h"
#include "core/scene/SceneJson.h"
#include "mesh/loading/SceneMeshes.h"
#include "render/gl/GlFormat.h"
#include "render/program/BuildThread.h"
#include "render/program/ProgramBuilder.h"
#include "ui/check/LiveCheck.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/shaders/ShaderFileSet.h"
#include "ui/viewport/CurrentContext.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/GuiMain.h"
#include "ui/window/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

using namespace phonglab;
using namespace phonglab::bench;

namespace {

// ---- PhongLab's paths: the real window, dock, controller and viewport -----

// How an edit's program is built and reaches the viewport.
enum class Builder {
    App,               // LiveShaderController: worker, first draw in the lent viewport context
    WorkerWarmsItself, // a BuildThread drawing once in its own context
    WorkerOnly,        // a BuildThread, no warm-up
    GuiThread,         // ProgramBuilder in the viewport's context
};

class PhongLabPath
{
public:
    PhongLabPath(const Scene &scene, const QSize &size, int samples, Builder builder);
    bool isReady() const { return m_ready; }
    QSize viewportPixels() const
    {
        return m_window->viewport()->size() * m_window->viewport()->devicePixelRatioF();
    }
    EditSample edit(const QByteArray &fragment);

private:
    using Applied = std::function<void(const BuildTimings &)>;
    // Starts building `fragment`; `applied` runs once the viewport has the program.
    void startBuild(const QByteArray &fragment, Applied applied);
    double steadyFrameMs();

    Builder m_builder;
    std::unique_ptr<MainWindow> m_window;
    std::unique_ptr<BuildThread> m_buildThread; // the worker paths'
    Applied m_applied;                          // ... and whom its reply goes to
    bool m_ready = false;
};

PhongLabPath::PhongLabPath(const Scene &scene, const QSize &size, int samples, Builder builder)
    : m_builder(builder)
{
    m_window = std::make_unique<MainWindow>();
    useMultisamplingInViewOnly(*m_window, samples); // as the app (GuiMain)
    if (const Result<> done = m_window->viewport()->setScene(scene); !done) {
        std::fprintf(stderr, "cannot show the scene: %s\n", qPrintable(done.error()));
        return;
    }
    m_window->viewport()->drawing().setShowLightMarkers(
        false);                               // the same single draw as the raw path
    m_window->viewport()->setFixedSize(size); // the raw path's framebuffer size
    m_window->show();
    QElapsedTimer wait;
    wait.start();
    while (m_window->viewport()->frames().frameStats().rendered == 0 && wait.elapsed() < 10000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    m_ready = m_window->viewport()->frames().frameStats().rendered > 0;
    if (!m_ready || builder == Builder::App || builder == Builder::GuiThread)
        return;
    m_buildThread = std::make_unique<BuildThread>();
    m_buildThread->setWarmUp(builder == Builder::WorkerWarmsItself);
    m_buildThread->setReceiver([this](BuildReply reply) {
        m_window->viewport()->program().adopt(std::move(reply.program));
        m_applied(reply.timings);
    });
    m_ready = bool(m_buildThread->start(m_window->viewport()->glContext().context()));
}

void PhongLabPath::startBuild(const QByteArray &fragment, Applied applied)
{
    Viewport *viewport = m_window->viewport();
    ShaderDock *dock = m_window->shaderDock();
    const ShaderSource vertexSource{dock->filePath(ShaderStage::Vertex),
                                    dock->text(ShaderStage::Vertex)};
    const ShaderSource fragmentSource{dock->filePath(ShaderStage::Fragment), fragment};
    switch (m_builder) {
    case Builder::App: {
        LiveShaderController *live = m_window->liveShaders();
        auto once = std::make_shared<QMetaObject::Connection>();
        *once = QObject::connect(live, &LiveShaderController::programApplied,
                                 [once, applied](const QByteArray &, const BuildTimings &t) {
                                     QObject::disconnect(*once);
                                     applied(t);
                                 });
        live->buildNow(); // where the debounce would fire
        return;
    }
    case Builder::WorkerWarmsItself:
    case Builder::WorkerOnly:
        m_applied = std::move(applied);
        m_buildThread->build(vertexSource, fragmentSource,
                             std::max(0, viewport->frames().framebufferSamples()),
                             viewport->currentScene().bindings);
        return;
    case Builder::GuiThread: {
        BuiltProgram built;
        {
            const CurrentContext current(*viewport);
            built = ProgramBuilder().build(vertexSource, fragmentSource, {},
                                           viewport->currentScene().bindings);
        }
        viewport->program().adopt(std::move(built.program));
        BuildTimings timings;
        timings.compileNs = built.compileNs;
        timings.linkNs = built.linkNs;
        applied(timings);
        return;
    }
    }
}

EditSample PhongLabPath::edit(const QByteArray &fragment)
{
    Viewport *viewport = m_window->viewport();
    if (m_builder == Builder::App)
        m_window->shaderDock()->editor(ShaderStage::Fragment)->setText(QString::fromUtf8(fragment));
    // The editor repaints the replaced text long before a real debounce
    // fires; let it, so that the clock measures the build alone.
    QElapsedTimer settle;
    settle.start();
    while (settle.elapsed() < 50)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);

    QEventLoop loop;
    QElapsedTimer clock;
    qint64 appliedAt = -1, frameAt = -1, lastTick = 0, maxGap = 0;
    BuildTimings timings;
    QTimer ticker;
    ticker.setTimerType(Qt::PreciseTimer);
    ticker.setInterval(1);
    QObject::connect(&ticker, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        maxGap = std::max(maxGap, now - lastTick);
        lastTick = now;
    });
    // The pixel: when the frame was handed to the window system (the
    // presenting thread's swapBuffers returned), as the raw path's.
    std::chrono::steady_clock::time_point start;
    const qint64 fromLoansBefore = viewport->frames().frameStats().fromLoans;
    auto framed = QObject::connect(viewport, &Viewport::frameSwapped, [&] {
        if (appliedAt >= 0 && frameAt < 0) {
            frameAt = std::chrono::duration_cast<std::chrono::nanoseconds>(
                          viewport->frames().lastPresentedAt() - start)
                          .count();
            loop.quit();
        }
    });
    QTimer::singleShot(20000, &loop, &QEventLoop::quit); // a build that never comes back
    start = std::chrono::steady_clock::now();
    clock.start();
    ticker.start();
    startBuild(fragment, [&](const BuildTimings &reply) {
        appliedAt = clock.nsecsElapsed();
        timings = reply;
    });
    if (frameAt < 0)
        loop.exec();
    m_applied = nullptr;
    QObject::disconnect(framed);
    EditSample s;
    if (frameAt < 0) {
        std::fprintf(stderr, "an edit never reached the screen\n");
        return s;
    }
    // The stretch ending in the frame itself (when it was presented on this thread).
    maxGap = std::max(maxGap, std::min(frameAt, clock.nsecsElapsed()) - lastTick);
    const qint64 maxGapToPixel = maxGap;
    // Typing goes on while the check of the new program runs: its stalls count too.
    QElapsedTimer checking;
    checking.start();
    while (m_window->liveCheck()->isChecking() && checking.elapsed() < 5000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
    ticker.stop();
    maxGap = std::max(maxGap, clock.nsecsElapsed() - lastTick);
    s.stallUntilCheckedMs = ms(maxGap);
    maxGap = maxGapToPixel;
    s.totalMs = ms(frameAt);
    s.compileMs = ms(timings.compileNs);
    s.linkMs = ms(timings.linkNs);
    s.warmMs = ms(timings.warmNs);
    // Presented by the trial, the frame reached the window before the
    // program was said to be applied: the GUI thread drew none.
    s.frameFromLoan = viewport->frames().frameStats().fromLoans > fromLoansBefore;
    s.frameMs = s.frameFromLoan ? 0.0 : ms(frameAt - appliedAt);
    s.otherMs = s.totalMs - s.compileMs - s.linkMs - s.warmMs - s.frameMs;
    s.stallMs = ms(maxGap);
    s.steadyMs = steadyFrameMs();
    return s;
}

// One more repaint with the program unchanged: what a frame costs once the
// driver has nothing left to compile.
double PhongLabPath::steadyFrameMs()
{
    Viewport *viewport = m_window->viewport();
    QEventLoop loop;
    QElapsedTimer clock;
    qint64 doneAt = -1;
    auto framed = QObject::connect(viewport, &Viewport::frameRendered, [&] {
        doneAt = clock.nsecsElapsed();
        loop.quit();
    });
    QTimer::singleShot(5000, &loop, &QEventLoop::quit);
    clock.start();
    viewport->frames().requestFrame();
    loop.exec();
    QObject::disconnect(framed);
    return doneAt < 0 ? 0.0 : ms(doneAt);
}

QString loadAverage()
{
    QFile file(QStringLiteral("/proc/loadavg"));
    return file.open(QIODevice::ReadOnly)
        ? QString::fromLatin1(file.readAll()).section(QLatin1Char(' '), 0, 2)
        : QStringLiteral("unknown");
}

struct Row {
    QString name;
    std::vector<EditSample> samples;
};

double column(const std::vector<EditSample> &samples, double EditSample::*field, double p)
{
    std::vector<double> values;
    for (const EditSample &s : samples)
        values.push_back(s.*field);
    return percentile(values, p);
}

void printTable(const std::vector<Row> &rows)
{
    std::printf("\n| path | edit→pixel median | p95 | compile | link | warm-up draw (worker "
                "thread; the app's with its trial and first frame) | first frame "
                "(GUI thread) | rest (queues, hops, adopt) | next frame, same program | longest "
                "GUI stall to the pixel, median | p95 | longest GUI stall until the check's "
                "verdict, median | p95 |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Row &row : rows) {
        const auto &v = row.samples;
        std::printf("| %s | %.1f ms | %.1f ms | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f ms "
                    "| %.1f ms | %.1f ms | %.1f ms |\n",
                    qPrintable(row.name), column(v, &EditSample::totalMs, 0.5),
                    column(v, &EditSample::totalMs, 0.95), column(v, &EditSample::compileMs, 0.5),
                    column(v, &EditSample::linkMs, 0.5), column(v, &EditSample::warmMs, 0.5),
                    column(v, &EditSample::frameMs, 0.5), column(v, &EditSample::otherMs, 0.5),
                    column(v, &EditSample::steadyMs, 0.5), column(v, &EditSample::stallMs, 0.5),
                    column(v, &EditSample::stallMs, 0.95),
                    column(v, &EditSample::stallUntilCheckedMs, 0.5),
                    column(v, &EditSample::stallUntilCheckedMs, 0.95));
    }
    for (const Row &row : rows) {
        const auto fromLoans = std::count_if(row.samples.begin(), row.samples.end(),
                                             [](const EditSample &s) { return s.frameFromLoan; });
        if (fromLoans > 0)
            std::printf("%s: %lld of %zu first frames presented by the trial in the lent context\n",
                        qPrintable(row.name), static_cast<long long>(fromLoans),
                        row.samples.size());
    }
    const double raw = column(rows.front().samples, &EditSample::totalMs, 0.5);
    std::printf("\n");
    for (std::size_t i = 1; i < rows.size(); ++i)
        std::printf("%s / raw GL (medians): %.2fx\n", qPrintable(rows[i].name),
                    column(rows[i].samples, &EditSample::totalMs, 0.5) / raw);
    // Each round's edits run back to back, so a change in the machine's
    // load touches both of a pair: the median of the pairs' ratios is the
    // steadier figure when the medians wander between runs.
    std::printf("\n");
    for (std::size_t i = 1; i < rows.size(); ++i) {
        std::vector<double> ratios;
        for (std::size_t k = 0; k < rows[i].samples.size() && k < rows[0].samples.size(); ++k)
            if (rows[0].samples[k].totalMs > 0)
                ratios.push_back(rows[i].samples[k].totalMs / rows[0].samples[k].totalMs);
        std::printf("%s / raw GL (median of the rounds' ratios): %.2fx\n", qPrintable(rows[i].name),
                    percentile(ratios, 0.5));
    }
}

} // namespace

int main(int argc, char **argv)
{
    // Every edit is a new text; a cached shader would hide the cost measured.
    qputenv("MESA_SHADER_CACHE_DISABLE", "true");
    QTemporaryDir recovery;
    qputenv("PHONGLAB_RECOVERY_DIR", recovery.path().toUtf8());
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true); // user copies of the shaders go to a test folder
    QCommandLineParser parser;
    parser.addHelpOption();
    parser.addOption({QStringLiteral("edits"), QStringLiteral("Edits per path (default 50)."),
                      QStringLiteral("N"), QStringLiteral("50")});
    parser.addOption({QStringLiteral("samples"),
                      QStringLiteral("MSAA samples of the viewport (default 4, as the app)."),
                      QStringLiteral("S"), QStringLiteral("4")});
    parser.process(app);
    const int edits = std::max(1, parser.value(QStringLiteral("edits")).toInt());
    const int samples = std::max(0, parser.value(QStringLiteral("samples")).toInt());
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(samples));

    // The default scene's tree alone: one mesh, one draw.
    SceneLoadResult loaded = loadSceneFile(defaultScenePath());
    if (!loaded.ok()) {
        std::fprintf(stderr, "%s\n", qPrintable(loaded.error));
        return 1;
    }
    Scene scene = *loaded.scene;
    scene.objects.resize(1);
    SceneMeshes meshes = loadSceneMeshes(scene);
    const auto mesh = meshes.entries.value(meshKey(scene, scene.objects.front())).mesh;
    const QSize size(800, 600);

    // Every path lives from the start and the edits go round-robin, so a
    // change in machine load during the run touches all rows alike.
    RawGlEditPath raw;
    if (!mesh || !raw.create(size, samples, scene, *mesh)) {
        std::fprintf(stderr, "cannot set up the raw GL path\n");
        return 1;
    }
    struct Mode {
        QString name;
        Builder builder;
    };
    const Mode modes[] = {
        {QStringLiteral("PhongLab: worker, warm-up in lent viewport context (the app)"),
         Builder::App},
        {QStringLiteral("PhongLab: worker, warm-up in worker context"), Builder::WorkerWarmsItself},
        {QStringLiteral("PhongLab: worker, no warm-up"), Builder::WorkerOnly},
        {QStringLiteral("PhongLab: GUI thread"), Builder::GuiThread}};
    std::vector<std::unique_ptr<PhongLabPath>> paths;
    std::vector<Row> rows{{QStringLiteral("raw GL (no Qt)"), {}}};
    for (const Mode &mode : modes) {
        paths.push_back(std::make_unique<PhongLabPath>(scene, size, samples, mode.builder));
        if (!paths.back()->isReady()) {
            std::fprintf(stderr, "%s: could not start\n", qPrintable(mode.name));
            return 1;
        }
        rows.push_back({mode.name, {}});
    }
    constexpr int kWarmUpRounds = 3;
    const QSize pixels = paths.front()->viewportPixels();
    std::printf(
        "viewport %dx%d px, %d samples, %d edits per path (+%d warm-up), %d CPUs, load %s\n",
        pixels.width(), pixels.height(), samples, edits, kWarmUpRounds, QThread::idealThreadCount(),
        qPrintable(loadAverage()));
    int serial = 0;
    for (int round = 0; round < kWarmUpRounds + edits; ++round) {
        for (std::size_t p = 0; p < rows.size(); ++p) {
            const QByteArray text =
                editedFragment(0.5 + 0.0001 * ++serial); // a new text every time
            const EditSample s = p == 0 ? raw.edit(text) : paths[p - 1]->edit(text);
            if (round >= kWarmUpRounds)
                rows[p].samples.push_back(s);
        }
    }
    printTable(rows);
    std::printf("load at the end: %s\n", qPrintable(loadAverage()));
    QDir(ShaderFileSet::userFolder()).removeRecursively();
    return 0;
}
