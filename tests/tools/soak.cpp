// A long session in one process, as a user's afternoon would be: live edits
// (good and broken alternating), scene reloads and mesh loads through the
// import child. Prints resident memory after a warm-up and at the end, and
// the live GL programs, buffers and textures of the viewport's share group.
// Not a test (it takes minutes): scripts/soak.sh runs it under Xvfb.
//   soak [--edits N] [--reloads N] [--loads N]
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "ui/scene/SceneLoadJob.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/viewport/CurrentContext.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>

using namespace phonglab;

namespace {

struct Counts {
    qint64 rssKiB = 0;
    int programs = 0, buffers = 0, textures = 0;
};

qint64 residentKiB()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n'))
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').first().toLongLong();
    return -1;
}

// GL names are small integers handed out in order: scanning the first few
// thousand with glIs* counts every object alive in the share group.
Counts count(MainWindow &window)
{
    Counts c;
    c.rssKiB = residentKiB();
    const CurrentContext current(*window.viewport());
    QOpenGLFunctions *gl = QOpenGLContext::currentContext()->functions();
    for (GLuint name = 1; name < 20000; ++name) {
        c.programs += gl->glIsProgram(name) ? 1 : 0;
        c.buffers += gl->glIsBuffer(name) ? 1 : 0;
        c.textures += gl->glIsTexture(name) ? 1 : 0;
    }
    return c;
}

void print(const char *when, const Counts &c)
{
    std::printf("%-22s resident %8.1f MiB   GL programs %4d   buffers %4d   textures %4d\n", when,
                double(c.rssKiB) / 1024.0, c.programs, c.buffers, c.textures);
    std::fflush(stdout);
}

bool waitFor(const std::function<bool()> &done, int timeoutMs)
{
    QElapsedTimer timer;
    timer.start();
    while (!done()) {
        if (timer.elapsed() > timeoutMs)
            return false;
        QTest::qWait(5);
    }
    return true;
}

class Session
{
public:
    explicit Session(MainWindow &window)
        : m_window(window)
    {
        LiveShaderController *live = window.liveShaders();
        QObject::connect(live, &LiveShaderController::programApplied, [this] { ++m_outcomes; });
        QObject::connect(live, &LiveShaderController::buildFailed, [this] { ++m_outcomes; });
        m_fragment = window.shaderDock()->editor(ShaderStage::Fragment)->text();
    }

    // Good edits scale the output; broken ones leave a statement unfinished.
    bool edit(int i)
    {
        const int before = m_outcomes;
        QString text = m_fragment;
        if (i % 2 == 0)
            text.replace(QStringLiteral("vec4(I, 1.0)"),
                         QStringLiteral("vec4(I * %1, 1.0)").arg(0.5 + 0.001 * i));
        else
            text.replace(QStringLiteral("vec4(I, 1.0);"),
                         QStringLiteral("vec4(I * %1, 1.0)").arg(i));
        m_window.shaderDock()->editor(ShaderStage::Fragment)->setText(text);
        return waitFor([&] { return m_outcomes > before && !m_window.liveShaders()->isBuilding(); },
                       20000);
    }

    bool open(const QString &path)
    {
        if (!m_window.document()->openFiles({path}))
            return false;
        return waitFor([&] { return !m_window.document()->loadJob()->isRunning(); }, 60000);
    }

private:
    MainWindow &m_window;
    QString m_fragment;
    int m_outcomes = 0;
};

int argument(const QStringList &args, const QString &name, int fallback)
{
    const qsizetype i = args.indexOf(name);
    return i >= 0 && i + 1 < args.size() ? args[i + 1].toInt() : fallback;
}

} // namespace

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    const int edits = argument(args, QStringLiteral("--edits"), 1000);
    const int reloads = argument(args, QStringLiteral("--reloads"), 100);
    const int loads = argument(args, QStringLiteral("--loads"), 100);
    test::useTestSettingsAndExactFrames();
    QSettings().setValue(QStringLiteral("editor/debounceMs"), 0);
    QTemporaryDir dir;
    qputenv("PHONGLAB_CACHE_DIR", QFile::encodeName(dir.filePath(QStringLiteral("cache"))));
    qputenv("PHONGLAB_RECOVERY_DIR", QFile::encodeName(dir.filePath(QStringLiteral("recovery"))));
    qputenv("PHONGLAB_RECOVERY_ANSWER", "discard");

    const QString scene = test::sourcePath(QStringLiteral("assets/scenes/default.json"));
    MainWindow window;
    QString error;
    if (const Result<> done = window.document()->openAndWait(scene); !done) {
        std::fprintf(stderr, "soak: %s\n", qPrintable(done.error()));
        return 1;
    }
    window.resize(900, 600);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)
        || !waitFor([&] { return window.viewport()->frames().frameStats().rendered > 0; }, 20000)) {
        std::fprintf(stderr, "soak: the window never drew a frame\n");
        return 1;
    }
    Session session(window);
    // Each mesh load is a file the cache has not seen: the import child runs.
    const QString mesh = test::sourcePath(QStringLiteral("assets/meshes/cloud.obj"));
    const auto meshCopy = [&](int i) {
        const QString copy = dir.filePath(QStringLiteral("mesh%1.obj").arg(i));
        QFile::copy(mesh, copy);
        return copy;
    };
    int failures = 0;
    const auto step = [&](int i) {
        failures += session.edit(i) ? 0 : 1;
        if (i % (std::max(1, edits / std::max(1, reloads))) == 0)
            failures += session.open(scene) ? 0 : 1;
        if (i % (std::max(1, edits / std::max(1, loads))) == 0)
            failures += session.open(meshCopy(i)) ? 0 : 1;
    };

    QElapsedTimer clock;
    clock.start();
    const int warmup = std::max(1, edits / 10);
    for (int i = 0; i < warmup; ++i)
        step(i);
    const Counts afterWarmup = count(window);
    print("after warm-up", afterWarmup);
    for (int i = warmup; i < edits; ++i) {
        step(i);
        if ((i + 1) % 100 == 0)
            std::printf("  %d edits, %.0f s\n", i + 1, clock.elapsed() / 1000.0),
                std::fflush(stdout);
    }
    const Counts end = count(window);
    print("at the end", end);
    const double growth =
        100.0 * double(end.rssKiB - afterWarmup.rssKiB) / double(afterWarmup.rssKiB);
    std::printf(
        "%d edits (good and broken alternating), %d scene reloads, %d mesh loads in %.0f s; "
        "%d steps failed\nresident memory growth after warm-up: %+.1f %% (aim: under 10 %%); "
        "GL objects: programs %+d, buffers %+d, textures %+d (aim: no growth)\n",
        edits, reloads, loads, clock.elapsed() / 1000.0, failures, growth,
        end.programs - afterWarmup.programs, end.buffers - afterWarmup.buffers,
        end.textures - afterWarmup.textures);
    const bool ok = failures == 0 && growth < 10.0 && end.programs <= afterWarmup.programs
        && end.buffers <= afterWarmup.buffers && end.textures <= afterWarmup.textures;
    std::printf("soak: %s\n", ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
}
