// Renders the pictures in README.md and docs/first-five-minutes.md with the
// app's own code: the main window on the default scene, a shader error in the
// live editor, the Lights dock, and the Performance dock after Fit to budget
// on the sphere scene (it runs build/app/phonglab bench). Run under Xvfb:
//   xvfb-run -a -s "-screen 0 1600x1000x24" build/tests/tools/make_screenshots docs/images
#include "core/scene/ResourcePaths.h"
#include "render/gl/GlFormat.h"
#include "ui/check/CheckOverlay.h"
#include "ui/check/LiveCheck.h"
#include "ui/check/VerdictDock.h"
#include "ui/performance/PerformanceDock.h"
#include "ui/scene/LightsDock.h"
#include "ui/scene/SceneEditDockSet.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"
#include "ui/window/WindowImage.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>

#include <cstdio>

using namespace phonglab;

namespace {

// Lets the window render and settle: background builds, dock layout.
void settle(int ms)
{
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < ms) {
        QApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(10);
    }
}

bool save(QWidget &window, const QDir &out, const char *name)
{
    const QString path = out.filePath(QString::fromLatin1(name));
    const bool ok = windowImage(window).save(path);
    std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
    return ok;
}

QByteArray readFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &text)
{
    QFile file(dir.filePath(name));
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write(text);
    return file.fileName();
}

// Until the live check has a verdict on the program just opened.
void settleUntilChecked(MainWindow &window, quint64 after)
{
    const LiveCheck *check = window.liveCheck();
    QElapsedTimer clock;
    clock.start();
    settle(500);
    while (clock.elapsed() < 60000
           && (check->isChecking() || !check->lastResult()
               || check->lastResult()->generation <= after))
        settle(200);
    settle(500);
}

quint64 lastGeneration(const MainWindow &window)
{
    const auto &last = window.liveCheck()->lastResult();
    return last ? last->generation : 0;
}

// Angel's shader on the course's scene (one light, his light in camera
// coordinates), edited two ways: a uniform nothing places, and two
// mistakes marked in the editor with the whole verdict in the Check dock.
bool shootCourseVerdicts(MainWindow &window, const QDir &out, const QTemporaryDir &state)
{
    const QString angel = QStringLiteral("tests/data/course/angel/");
    QJsonObject scene =
        QJsonDocument::fromJson(readFile(QStringLiteral("tests/data/course/scene.json"))).object();
    QJsonArray lights = scene.value(QStringLiteral("lights")).toArray();
    lights.removeLast();
    scene.insert(QStringLiteral("lights"), lights);
    scene.insert(
        QStringLiteral("bindings"),
        QJsonObject{{QStringLiteral("lightPosition"), QStringLiteral("light-position-camera")}});
    const QString scenePath =
        writeFile(state, QStringLiteral("course.json"), QJsonDocument(scene).toJson());
    const QByteArray fragment = readFile(angel + QStringLiteral("phong.frag"));
    if (scenePath.isEmpty() || fragment.isEmpty())
        return false;

    QByteArray zork = fragment;
    zork.replace("uniform float shininess;", "uniform float shininess;\nuniform vec3 uZork;");
    zork.replace("fColor.a = 1.0;", "fColor.rgb += uZork;\n    fColor.a = 1.0;");
    quint64 before = lastGeneration(window);
    if (!window.document()->openSubmission(scenePath, angel + QStringLiteral("phong.vert"),
                                           writeFile(state, QStringLiteral("zork.frag"), zork)))
        return false;
    settleUntilChecked(window, before);
    window.docks().uniforms->raise();
    window.liveCheck()->uniformToPlace(QStringLiteral("uZork"));
    settle(800);
    bool ok = save(window, out, "verdict-unplaced.png");

    QByteArray wrong = fragment;
    wrong.replace("ambient + fatt * (diffuse + specular)", "ambient + (diffuse + specular)");
    wrong.replace("reflect(-l, n)", "reflect(l, n)");
    before = lastGeneration(window);
    if (!window.document()->openSubmission(
            scenePath, angel + QStringLiteral("phong.vert"),
            writeFile(state, QStringLiteral("mistakes.frag"), wrong)))
        return false;
    settleUntilChecked(window, before);
    VerdictDock *verdict = window.liveCheck()->verdictDock();
    verdict->show();
    verdict->raise();
    window.shaderDock()->editor(ShaderStage::Fragment)->setFirstVisibleLine(10);
    settle(800);
    return save(window, out, "verdict-two-mistakes.png") && ok;
}

} // namespace

int main(int argc, char **argv)
{
    QTemporaryDir state;
    qputenv("PHONGLAB_RECOVERY_DIR", state.filePath(QStringLiteral("recovery")).toUtf8());
    qputenv("PHONGLAB_CACHE_DIR", state.filePath(QStringLiteral("cache")).toUtf8());
    QStandardPaths::setTestModeEnabled(true); // no user settings, no recent files
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(4));
    QApplication app(argc, argv);
    const QDir out(argc > 1 ? QString::fromLocal8Bit(argv[1]) : QStringLiteral("docs/images"));
    QDir().mkpath(out.path());

    // The Performance dock measures the view with the phonglab binary beside
    // this tool's build folder; the window reads PHONGLAB_EXE once, when it
    // is made (StartupOptions).
    if (qEnvironmentVariableIsEmpty("PHONGLAB_EXE"))
        qputenv("PHONGLAB_EXE",
                (QCoreApplication::applicationDirPath() + QStringLiteral("/../../app/phonglab"))
                    .toUtf8());
    MainWindow window; // at its default size: a share of the screen (DefaultLayout)
    QString error;
    if (const Result<> done = window.document()->openAndWait(defaultScenePath()); !done) {
        std::fprintf(stderr, "make_screenshots: %s\n", qPrintable(done.error()));
        return 1;
    }
    window.show();
    settle(2500);
    bool ok = save(window, out, "app.png");

    // A typo in the fragment shader: the last good program keeps rendering,
    // the error sits on its line.
    window.shaderDock()->raise();
    ShaderEditor *fragment = window.shaderDock()->editor(ShaderStage::Fragment);
    QByteArray code = fragment->code();
    code.replace("vec3 V = normalize(-positionCam);", "vec3 V = normalise(-positionCam);");
    fragment->setCode(code);
    window.liveShaders()->buildNow();
    settle(2500);
    const int errorLine = int(code.left(code.indexOf("normalise(")).count('\n'));
    fragment->setFirstVisibleLine(std::max(0, errorLine - 8));
    settle(300);
    ok = save(window, out, "shader-error.png") && ok;

    window.editDocks()->lightsDock()->raise();
    settle(800);
    ok = save(window, out, "lights.png") && ok;

    // The check on its own scene with reflect(L, N) typed in: the verdict in
    // the status bar, the heatmap, the split view, the pixel inspector.
    fragment->setCode(code.replace("normalise(", "normalize("));
    if (const Result<> done =
            window.document()->openAndWait(assetPath(QStringLiteral("scenes/check.json")));
        !done) {
        std::fprintf(stderr, "make_screenshots: %s\n", qPrintable(done.error()));
        return 1;
    }
    settle(1500);
    QByteArray wrong = fragment->code();
    wrong.replace("reflect(-L, N)", "reflect(L, N)");
    fragment->setCode(wrong);
    window.liveShaders()->buildNow();
    settle(3000);
    LiveCheck *check = window.liveCheck();
    check->setOverlayMode(OverlayMode::Heatmap);
    settle(500);
    ok = save(window, out, "check-heatmap.png") && ok;
    check->setOverlayMode(OverlayMode::Split);
    check->overlay()->setDivider(0.45);
    settle(500);
    ok = save(window, out, "check-split.png") && ok;
    check->setOverlayMode(OverlayMode::Off);
    check->inspect(window.viewport()->rect().center() + QPoint(40, 10));
    settle(1500);
    ok = save(window, out, "check-inspector.png") && ok;
    fragment->setCode(code);
    window.liveShaders()->buildNow();
    ok = shootCourseVerdicts(window, out, state) && ok;

    // Fit to budget on the sphere scene (the dock measures with the phonglab
    // binary set before the window was made, above).
    if (const Result<> done =
            window.document()->openAndWait(assetPath(QStringLiteral("scenes/sphere.json")));
        !done) {
        std::fprintf(stderr, "make_screenshots: %s\n", qPrintable(done.error()));
        return 1;
    }
    PerformanceDock *performance = window.performanceDock();
    performance->show(); // as View > Performance Dock does
    performance->raise();
    window.resizeDocks({performance}, {560}, Qt::Horizontal);
    settle(1500);
    performance->fitToBudget();
    QElapsedTimer measuring;
    measuring.start();
    while (performance->isMeasuring() && measuring.elapsed() < 180000)
        settle(200);
    settle(2500);
    std::printf("%s\n", qPrintable(performance->reportText()));
    ok = save(window, out, "performance.png") && ok;
    return ok ? 0 : 1;
}
