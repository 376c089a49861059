// The viewport's frame against a raw-GL floor that presents (prints figures;
// not a test).
//
//   build/tests/bench/bench_frame [--frames N] [--samples S]     (under X: xvfb-run -a)
//
// Both draw every object of the default scene with the shipped Phong
// program and the same MSAA and present the frame: PhongLab's main window
// (QOpenGLWidget: its framebuffer, the resolve and the window's composition,
// then swapBuffers) and RawGlFramePath (a bare QWindow drawing into its own
// default framebuffer, then swapBuffers). A frame is the interval between
// two frames reaching the window while frames are asked for back to back,
// event loop included, at 800x600 and at the viewport's size in the window
// as it first opens. Blocks of frames alternate between the two so that the
// machine's load touches both alike.
#include "BenchHelpers.h"
#include "EditSample.h"
#include "RawGlFramePath.h"
#include "render/GlFormat.h"
#include "ui/GuiMain.h"
#include "ui/MainWindow.h"
#include "ui/Viewport.h"

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

using namespace phonglab;
using namespace phonglab::bench;

namespace {

constexpr int kBlock = 20;        // frames per block before switching paths
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
        m_window->viewport()->setShowLightMarkers(false); // the raw path draws none
        if (const Result<> set = m_window->viewport()->setScene(scene); !set)
            std::fprintf(stderr, "cannot show the scene: %s\n", qPrintable(set.error()));
        m_window->show();
        QElapsedTimer wait;
        wait.start();
        while (m_window->viewport()->framesRendered() == 0 && wait.elapsed() < 10000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    }
    bool isReady() const { return m_window->viewport()->framesRendered() > 0; }
    int samples() const { return m_window->viewport()->framebufferSamples(); }
    QSize pixels() const
    {
        return m_window->viewport()->size() * m_window->viewport()->devicePixelRatioF();
    }
    // `count` frames back to back: the intervals between frameSwapped, and
    // the draw times the status bar reports (glFinish-timed, per frame).
    void run(int count, std::vector<double> &intervals, std::vector<double> &draws)
    {
        Viewport *viewport = m_window->viewport();
        QEventLoop loop;
        QElapsedTimer clock;
        int seen = -1; // the first swap starts the clock
        double lastDraw = 0;
        auto drawn = QObject::connect(viewport, &Viewport::frameRendered,
                                      [&] { lastDraw = viewport->frameTimes().latestMs(); });
        auto swapped = QObject::connect(viewport, &QOpenGLWidget::frameSwapped, [&] {
            if (seen >= 0) {
                intervals.push_back(ms(clock.nsecsElapsed()));
                draws.push_back(lastDraw);
            }
            clock.start();
            if (++seen >= count)
                loop.quit();
            else
                viewport->update();
        });
        QTimer::singleShot(60000, &loop, &QEventLoop::quit);
        settle();
        viewport->update();
        loop.exec();
        QObject::disconnect(drawn);
        QObject::disconnect(swapped);
    }

private:
    std::unique_ptr<MainWindow> m_window;
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

void measure(const Scene &scene, const SceneMeshes &meshes, const QSize *fixedSize, int samples,
             int frames, const char *label)
{
    ViewportFrames phonglab(scene, fixedSize, samples);
    if (!phonglab.isReady()) {
        std::fprintf(stderr, "%s: the viewport drew nothing\n", label);
        return;
    }
    const QSize size = phonglab.pixels();
    if (phonglab.samples() != samples) { // the floor must resolve as many samples
        std::fprintf(stderr, "%s: the viewport has %d samples, not %d\n", label, phonglab.samples(),
                     samples);
        return;
    }
    RawGlFramePath raw, contained;
    if (!raw.create(size, samples, scene, meshes)
        || !contained.create(size, samples, scene, meshes,
                             RawGlFramePath::Placement::InsideMainWindow))
        return;
    std::vector<double> rawFrames, containedFrames, viewportFrames, draws, ignored, ignoredDraws;
    phonglab.run(kWarmUpFrames, ignored, ignoredDraws);
    runRaw(raw, kWarmUpFrames, ignored);
    runRaw(contained, kWarmUpFrames, ignored);
    while (int(rawFrames.size()) < frames) {
        phonglab.run(kBlock, viewportFrames, draws);
        runRaw(raw, kBlock, rawFrames);
        runRaw(contained, kBlock, containedFrames);
    }
    const double raw50 = percentile(rawFrames, 0.5), raw95 = percentile(rawFrames, 0.95);
    const double vp50 = percentile(viewportFrames, 0.5), vp95 = percentile(viewportFrames, 0.95);
    const double child50 = percentile(containedFrames, 0.5);
    const double child95 = percentile(containedFrames, 0.95);
    std::printf("| %s | %dx%d | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.2fx / %.2fx | "
                "%.2fx / %.2fx | %.2f |\n",
                label, size.width(), size.height(), raw50, raw95, child50, child95, vp50, vp95,
                vp50 / raw50, vp95 / raw95, vp50 / child50, vp95 / child95, percentile(draws, 0.5));
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
    std::printf("\nframe intervals in ms, p50 / p95:\n");
    std::printf("\n| size | pixels | raw GL, own window | raw GL, native child of a main window "
                "| PhongLab viewport | viewport / raw own window | viewport / raw native child "
                "| viewport draw p50 (per frame) |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    const QSize fixed(800, 600);
    measure(loaded->scene, loaded->meshes, &fixed, samples, frames, "800x600");
    measure(loaded->scene, loaded->meshes, nullptr, samples, frames, "window's default");
    std::printf("\nload at the end: %s\n", qPrintable(loadAverage()));
    return 0;
}
