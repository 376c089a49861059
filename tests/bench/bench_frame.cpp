// The viewport's frame against a raw-GL floor that presents (prints figures;
// not a test).
//
//   build/tests/bench/bench_frame [--frames N] [--samples S]     (under X: xvfb-run -a)
//
// Both draw every object of the default scene with the shipped Phong
// program and the same MSAA and present the frame: PhongLab's main window
// (the view's native window, its multisampled framebuffer, swapBuffers) and
// RawGlFramePath (a bare QWindow drawing into its own default framebuffer,
// then swapBuffers; also as a native child of a main window, and redoing a
// QOpenGLWidget's steps). The main window is measured once its start's
// check has run, as a user's is while working. A frame is the interval between
// two frames reaching the window while frames are asked for back to back,
// event loop included, at 800x600 and at the viewport's size in the window
// as it first opens. Short blocks of frames alternate between the paths so
// that the machine's load touches all alike.
#include "BenchHelpers.h"
#include "EditSample.h"
#include "RawGlFramePath.h"
#include "render/gl/GlFormat.h"
#include "ui/check/LiveCheck.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/GuiMain.h"
#include "ui/window/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <cstdio>
#include <memory>
#include <optional>

using namespace phonglab;
using namespace phonglab::bench;

namespace {

// Frames per block before switching paths. The machine's slow spells last
// a few hundred milliseconds: short blocks spread one over every path, where
// long ones leave it to whichever path it hits and decide that path's p95.
constexpr int kBlock = 10;
constexpr int kWarmUpFrames = 30; // first frames: programs compiled, caches warm

// Before each block: the other paths' pending window work is done, so that
// no block pays for another's.
void settle()
{
    for (int i = 0; i < 3; ++i)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
}

// PhongLab's path: the real window, asked for frame after frame.
class ViewportFrames
{
public:
    ViewportFrames(const Scene &scene, const QSize *fixedSize, int samples)
    {
        m_window = std::make_unique<MainWindow>();
        useMultisamplingInViewOnly(*m_window, samples); // as the app (GuiMain)
        if (fixedSize)
            m_window->viewport()->setFixedSize(*fixedSize);
        m_window->viewport()->drawing().setShowLightMarkers(false); // the raw path draws none
        if (const Result<> set = m_window->viewport()->setScene(scene); !set)
            std::fprintf(stderr, "cannot show the scene: %s\n", qPrintable(set.error()));
        m_window->show();
        QElapsedTimer wait;
        wait.start();
        while (m_window->viewport()->frames().frameStats().rendered == 0 && wait.elapsed() < 10000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        // The start's check of the frame against the exact image draws the
        // reference on the CPU, where llvmpipe rasterises too: frames drawn
        // meanwhile are slower. Steady frames are measured after it.
        QElapsedTimer checking;
        checking.start();
        while (m_window->liveCheck()->isChecking() && checking.elapsed() < 30000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        m_checkMs = ms(checking.nsecsElapsed());
    }
    // How long the start's check ran after the first frame (ms).
    double checkMs() const { return m_checkMs; }
    bool isReady() const { return m_window->viewport()->frames().frameStats().rendered > 0; }
    int samples() const { return m_window->viewport()->frames().framebufferSamples(); }
    QSize pixels() const
    {
        return m_window->viewport()->size() * m_window->viewport()->devicePixelRatioF();
    }
    QSize windowPixels() const { return m_window->size() * m_window->devicePixelRatioF(); }

    // Where each frame's interval went: from the previous frame's swap to
    // the end of drawing less the draw (the event loop up to the frame), the
    // draw (first GL call to glFinish, widgets over the view included: the
    // status bar's figure), and the draw's end to frameSwapped (the swap).
    struct Phases {
        std::vector<double> beforeDraw, draw, afterDraw;
    };
    // `count` frames back to back: the intervals between frameSwapped.
    void run(int count, std::vector<double> &intervals, Phases &phases)
    {
        Viewport *viewport = m_window->viewport();
        QEventLoop loop;
        QElapsedTimer clock;
        int seen = -1; // the first swap starts the clock
        double lastDraw = 0, paintEnd = 0;
        auto drawn = QObject::connect(viewport, &Viewport::frameRendered, [&] {
            lastDraw = viewport->frames().frameTimes().latestMs();
            paintEnd = ms(clock.nsecsElapsed());
        });
        auto swapped = QObject::connect(viewport, &Viewport::frameSwapped, [&] {
            if (seen >= 0) {
                const double now = ms(clock.nsecsElapsed());
                intervals.push_back(now);
                phases.beforeDraw.push_back(paintEnd - lastDraw);
                phases.draw.push_back(lastDraw);
                phases.afterDraw.push_back(now - paintEnd);
            }
            clock.start();
            if (++seen >= count)
                loop.quit();
            else
                viewport->frames().requestFrame();
        });
        QTimer::singleShot(60000, &loop, &QEventLoop::quit);
        settle();
        viewport->frames().requestFrame();
        loop.exec();
        QObject::disconnect(drawn);
        QObject::disconnect(swapped);
    }

private:
    std::unique_ptr<MainWindow> m_window;
    double m_checkMs = 0;
};

// `frames` presented frames of `raw`, with the application's events
// handled between them as its loop would.
void runRaw(RawGlFramePath &raw, int frames, std::vector<double> &intervals)
{
    settle();
    raw.drawFrame(); // the first frame starts the clock, as on the viewport's path
    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < frames; ++i) {
        QCoreApplication::processEvents();
        raw.drawFrame();
        intervals.push_back(ms(clock.nsecsElapsed()));
        clock.start();
    }
}

// The steps of `frames` raw frames, each timed on its own (glFinish after
// each); medians per step.
RawGlFramePath::Steps medianSteps(RawGlFramePath &raw, int frames)
{
    settle();
    std::vector<double> draw, resolve, upload, compose, swap;
    for (int i = 0; i < frames; ++i) {
        QCoreApplication::processEvents();
        const RawGlFramePath::Steps s = raw.drawTimedFrame();
        draw.push_back(s.draw);
        resolve.push_back(s.resolve);
        upload.push_back(s.upload);
        compose.push_back(s.compose);
        swap.push_back(s.swap);
    }
    return {percentile(draw, 0.5), percentile(resolve, 0.5), percentile(upload, 0.5),
            percentile(compose, 0.5), percentile(swap, 0.5)};
}

struct Measured {
    QString label;
    QSize size;
    std::vector<double> raw, contained, composed, viewport;
    ViewportFrames::Phases phases;
    RawGlFramePath::Steps rawSteps, composedSteps;
};

std::optional<Measured> measure(const Scene &scene, const SceneMeshes &meshes,
                                const QSize *fixedSize, int samples, int frames, const char *label)
{
    ViewportFrames phonglab(scene, fixedSize, samples);
    if (!phonglab.isReady()) {
        std::fprintf(stderr, "%s: the viewport drew nothing\n", label);
        return std::nullopt;
    }
    std::printf("%s: frames measured after the start's check of the frame, which ran %.0f ms\n",
                label, phonglab.checkMs());
    Measured m{QString::fromLatin1(label), phonglab.pixels(), {}, {}, {}, {}, {}, {}, {}};
    if (phonglab.samples() != samples) { // the floor must resolve as many samples
        std::fprintf(stderr, "%s: the viewport has %d samples, not %d\n", label, phonglab.samples(),
                     samples);
        return std::nullopt;
    }
    using P = RawGlFramePath;
    RawGlFramePath raw, contained, composed;
    if (!raw.create(m.size, samples, scene, meshes)
        || !contained.create(m.size, samples, scene, meshes, P::Placement::InsideMainWindow)
        || !composed.create(m.size, samples, scene, meshes, P::Placement::OwnWindow,
                            P::Presentation::ThroughTexture, phonglab.windowPixels()))
        return std::nullopt;
    std::vector<double> ignored;
    ViewportFrames::Phases ignoredPhases;
    phonglab.run(kWarmUpFrames, ignored, ignoredPhases);
    for (RawGlFramePath *path : {&raw, &contained, &composed})
        runRaw(*path, kWarmUpFrames, ignored);
    while (int(m.raw.size()) < frames) {
        phonglab.run(kBlock, m.viewport, m.phases);
        runRaw(raw, kBlock, m.raw);
        runRaw(contained, kBlock, m.contained);
        runRaw(composed, kBlock, m.composed);
    }
    m.rawSteps = medianSteps(raw, frames / 2);
    m.composedSteps = medianSteps(composed, frames / 2);
    return m;
}

void printIntervals(const Measured &m)
{
    const double raw50 = percentile(m.raw, 0.5), raw95 = percentile(m.raw, 0.95);
    const double vp50 = percentile(m.viewport, 0.5), vp95 = percentile(m.viewport, 0.95);
    const double child50 = percentile(m.contained, 0.5), child95 = percentile(m.contained, 0.95);
    const double comp50 = percentile(m.composed, 0.5), comp95 = percentile(m.composed, 0.95);
    std::printf("| %s | %dx%d | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | "
                "%.2fx / %.2fx | %.2fx / %.2fx | %.2fx / %.2fx |\n",
                qPrintable(m.label), m.size.width(), m.size.height(), raw50, raw95, child50,
                child95, comp50, comp95, vp50, vp95, vp50 / raw50, vp95 / raw95, vp50 / child50,
                vp95 / child95, vp50 / comp50, vp95 / comp95);
}

void printSteps(const Measured &m)
{
    const auto &p = m.phases;
    std::printf("| %s | viewport (frame as presented) | %.2f | draw %.2f | %.2f | %.2f |\n",
                qPrintable(m.label), percentile(p.beforeDraw, 0.5), percentile(p.draw, 0.5),
                percentile(p.afterDraw, 0.5), percentile(m.viewport, 0.5));
    // The tail: the same split, averaged over the frames at or above the
    // viewport's p90 interval (where p95 comes from).
    const double p90 = percentile(m.viewport, 0.9);
    double before = 0, draw = 0, after = 0, frame = 0;
    int slow = 0;
    for (std::size_t i = 0; i < m.viewport.size() && i < p.draw.size(); ++i) {
        if (m.viewport[i] < p90)
            continue;
        before += p.beforeDraw[i];
        draw += p.draw[i];
        after += p.afterDraw[i];
        frame += m.viewport[i];
        ++slow;
    }
    if (slow > 0)
        std::printf(
            "| %s | viewport, mean of its slowest 10%% | %.2f | draw %.2f | %.2f | %.2f |\n",
            qPrintable(m.label), before / slow, draw / slow, after / slow, frame / slow);
    const auto row = [&m](const char *path, const RawGlFramePath::Steps &s) {
        std::printf("| %s | %s (glFinish after each step) | draw %.2f | resolve %.2f | upload "
                    "%.2f | compose %.2f | swap %.2f |\n",
                    qPrintable(m.label), path, s.draw, s.resolve, s.upload, s.compose, s.swap);
    };
    row("raw GL, own window", m.rawSteps);
    row("raw GL, the widget's steps", m.composedSteps);
}

QString loadAverage()
{
    QFile file(QStringLiteral("/proc/loadavg"));
    return file.open(QIODevice::ReadOnly)
        ? QString::fromLatin1(file.readAll()).section(QLatin1Char(' '), 0, 2)
        : QStringLiteral("unknown");
}

} // namespace

int main(int argc, char **argv)
{
    QTemporaryDir recovery;
    qputenv("PHONGLAB_RECOVERY_DIR", recovery.path().toUtf8());
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true); // no user settings: the window's default size
    QCommandLineParser parser;
    parser.addHelpOption();
    parser.addOption({QStringLiteral("frames"), QStringLiteral("Frames per path (default 200)."),
                      QStringLiteral("N"), QStringLiteral("200")});
    parser.addOption({QStringLiteral("samples"),
                      QStringLiteral("MSAA samples (default 4, as the app)."), QStringLiteral("S"),
                      QStringLiteral("4")});
    parser.process(app);
    const int frames = std::max(kBlock, parser.value(QStringLiteral("frames")).toInt());
    const int samples = std::max(0, parser.value(QStringLiteral("samples")).toInt());
    // No vsync for either path: on a real display it would hold both to the
    // refresh rate and hide the difference.
    QSurfaceFormat format = phonglabSurfaceFormat(samples);
    format.setSwapInterval(0);
    QSurfaceFormat::setDefaultFormat(format);
    const auto loaded = loadDefaultScene();
    if (!loaded)
        return 1;
    std::printf("default scene (every object), %d samples, %d frames per path, %d CPUs, load %s\n",
                samples, frames, QThread::idealThreadCount(), qPrintable(loadAverage()));
    const QSize fixed(800, 600);
    std::vector<Measured> all;
    if (auto m = measure(loaded->scene, loaded->meshes, &fixed, samples, frames, "800x600"))
        all.push_back(std::move(*m));
    if (auto m =
            measure(loaded->scene, loaded->meshes, nullptr, samples, frames, "window's default"))
        all.push_back(std::move(*m));
    std::printf("\nframe intervals in ms, p50 / p95:\n");
    std::printf("\n| size | pixels | raw GL, own window | raw GL, native child of a main window "
                "| raw GL, the widget's steps | PhongLab viewport | viewport / raw own window "
                "| viewport / raw native child | viewport / raw widget's steps |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (const Measured &m : all)
        printIntervals(m);
    std::printf("\nwhere the frame goes, ms, p50 of each:\n");
    std::printf("\nviewport: | size | path | swap to the frame's start (event loop) | draw (to "
                "glFinish, overlays included) | draw's end to swapped (the swap) | frame |\n");
    std::printf("raw paths: | size | path | steps, each timed alone with glFinish after it |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (const Measured &m : all)
        printSteps(m);
    std::printf("\nload at the end: %s\n", qPrintable(loadAverage()));
    return 0;
}
