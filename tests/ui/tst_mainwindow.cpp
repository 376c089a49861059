// The editor window end to end, on a real GL context (Mesa llvmpipe under
// Xvfb): the default scene is drawn and lit, bad files leave the scene alone,
// the mouse moves the camera, reset restores it, and saving round-trips.

#include "PixelDiff.h"
#include "ResultChecks.h"
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "core/scene/SceneJson.h"
#include "core/view/CameraFraming.h"
#include "ui/viewport/FrameStatsLabel.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"
#include "ui/window/WindowImage.h"

#include <QDir>
#include <QLabel>
#include <QMenuBar>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>
#include <memory>

using namespace phonglab;
using namespace phonglab::test;

namespace {

constexpr int kBackgroundTolerance = 6; // 8-bit steps, per channel
constexpr int kTintMargin = 40;         // how much one channel must beat the other

QString defaultScenePathInSource()
{
    return test::sourcePath(QStringLiteral("assets/scenes/default.json"));
}

QRgb toRgb(const glm::dvec3 &c)
{
    return qRgb(qRound(c.r * 255.0), qRound(c.g * 255.0), qRound(c.b * 255.0));
}

struct FrameColours {
    double foregroundFraction = 0.0; // pixels that are not background
    double warmFraction = 0.0;       // red clearly above blue
    double coolFraction = 0.0;       // blue clearly above red
};

FrameColours analyse(const QImage &frame, QRgb background)
{
    const QImage image = frame.convertToFormat(QImage::Format_RGB32);
    qint64 foreground = 0, warm = 0, cool = 0;
    for (int y = 0; y < image.height(); ++y) {
        const auto *line = reinterpret_cast<const QRgb *>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = line[x];
            if (!differsFrom(p, background, kBackgroundTolerance))
                continue;
            ++foreground;
            warm += qRed(p) > qBlue(p) + kTintMargin;
            cool += qBlue(p) > qRed(p) + kTintMargin;
        }
    }
    const double total = double(image.width()) * image.height();
    return {foreground / total, warm / total, cool / total};
}

// Saving into another folder rewrites relative mesh paths; the same meshes
// are then named differently, so compare what the names resolve to.
Scene withResolvedMeshes(Scene scene)
{
    for (SceneObject &object : scene.objects)
        object.mesh = QDir::cleanPath(scene.resolveMeshPath(object.mesh));
    return scene;
}

void writeFile(const QString &path, const QByteArray &contents)
{
    QFile file(path);
    QVERIFY2(file.open(QIODevice::WriteOnly), qPrintable(file.errorString()));
    file.write(contents);
}

} // namespace

class TestMainWindow : public test::WindowPerTest
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();

    void opensDefaultSceneAndDrawsLitObject();
    void showsFrameStatsAndRenderer();
    void frameStatsSayWhatTheyMeasureAndChangeTwiceASecond();
    void lightMarkersCanBeHidden();
    void failedOpenKeepsCurrentScene_data();
    void failedOpenKeepsCurrentScene();
    void leftDragOrbitsCamera();
    void rightDragPansAndWheelZooms();
    void resetRestoresOriginalCamera_data();
    void resetRestoresOriginalCamera();
    void inputOnTheViewsOwnWindowReachesTheView();
    void saveThenReopenGivesEqualScene();

private:
    void drag(Qt::MouseButton button, QPoint by);
    void zoom(int notches); // > 0 towards the scene, as a wheel turned away from the user
    void saveArtifact(const QString &name, const QImage &image) const;

    Scene m_loaded; // default.json exactly as on disk
    Scene m_shown;  // ... as the view shows it: its camera framed for the view's shape
};

void TestMainWindow::initTestCase()
{
    // Saving adds to the recent files: keep them out of the user's settings.
    // No multisampling: pixel colours are single fragments, easier to reason about.
    test::useTestSettingsAndExactFrames();
    const SceneLoadResult loaded = loadSceneFile(defaultScenePathInSource());
    QVERIFY2(loaded.ok(), qPrintable(loaded.error));
    m_loaded = *loaded.scene;
}

void TestMainWindow::init()
{
    openWindow(defaultScenePathInSource(), {800, 600});
    m_shown = m_loaded;
    const QSize pixels = viewport()->size() * viewport()->devicePixelRatioF();
    m_shown.camera =
        framedCamera(m_loaded.camera, objectBoundsCorners(m_loaded, viewport()->meshInfo()),
                     double(pixels.width()) / pixels.height());
}

void TestMainWindow::drag(Qt::MouseButton button, QPoint by)
{
    const QPoint start = viewport()->rect().center();
    QTest::mousePress(viewport(), button, Qt::NoModifier, start);
    // Several steps, as a real drag would arrive.
    for (int step = 1; step <= 4; ++step)
        QTest::mouseMove(viewport(), start + by * step / 4);
    QTest::mouseRelease(viewport(), button, Qt::NoModifier, start + by);
}

void TestMainWindow::zoom(int notches)
{
    const QPointF centre = QPointF(viewport()->rect().center());
    QWheelEvent wheel(centre, viewport()->mapToGlobal(centre), QPoint(), QPoint(0, 120 * notches),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &wheel);
}

void TestMainWindow::saveArtifact(const QString &name, const QImage &image) const
{
    const QString dir = qEnvironmentVariable("PHONGLAB_TEST_ARTIFACTS");
    if (!dir.isEmpty() && QDir().mkpath(dir))
        image.save(QDir(dir).filePath(name));
}

void TestMainWindow::opensDefaultSceneAndDrawsLitObject()
{
    // The scene as loaded, its camera moved back only as far as this view's
    // shape needs to show every object (none is cut off: tst_windowlayout).
    QCOMPARE(viewport()->currentScene(), m_shown);
    QVERIFY2(m_window->windowTitle().contains(QStringLiteral("default.json")),
             qPrintable(m_window->windowTitle()));

    const QImage image = frame();
    QVERIFY(!image.isNull());
    saveArtifact(QStringLiteral("mainwindow-viewport.png"), image);
    saveArtifact(QStringLiteral("mainwindow-window.png"), windowImage(*m_window));

    const FrameColours stats = analyse(image, toRgb(m_loaded.background));
    QVERIFY2(stats.foregroundFraction > 0.05,
             qPrintable(QString::number(stats.foregroundFraction)));
    QVERIFY(viewport()->drawing().showLightMarkers());
}

void TestMainWindow::showsFrameStatsAndRenderer()
{
    QStringList texts;
    QTRY_VERIFY([&] {
        texts.clear();
        for (const QLabel *label : m_window->statusBar()->findChildren<QLabel *>())
            texts << label->text();
        return texts.join(u'|').contains(QStringLiteral(" ms"))
            && texts.join(u'|').contains(QStringLiteral("triangles"));
    }());
    QVERIFY2(texts.join(u'|').contains(QStringLiteral("OpenGL")), qPrintable(texts.join(u'|')));
    QVERIFY(viewport()->glContext().glRendererName().startsWith(QStringLiteral("OpenGL")));
}

// The readout names its figure and averages it; it changes at most every
// ReadoutPace::kIntervalMs (a label's change costs a relayout and a repaint), except
// for a new triangle count, which shows at once.
void TestMainWindow::frameStatsSayWhatTheyMeasureAndChangeTwiceASecond()
{
    auto *label = m_window->statusBar()->findChild<FrameStatsLabel *>();
    QVERIFY(label);
    QTRY_VERIFY(label->text().startsWith(QStringLiteral("draw ")));
    qint64 nowMs = 1'000'000; // the pace's clock, moved on by hand
    label->setReadoutClock([&nowMs] { return nowMs; });
    QVERIFY2(label->toolTip().contains(QStringLiteral("glFinish"))
                 && label->toolTip().contains(QStringLiteral("last second")),
             qPrintable(label->toolTip()));
    label->showFrame(11.0, 100); // new triangles: at once
    const QString first = label->text();
    QVERIFY2(first.startsWith(QStringLiteral("draw 11.00 ms · 100 triangles")), qPrintable(first));
    for (int i = 1; i <= 50; ++i)
        label->showFrame(11.0 + i, 100); // a burst within the interval: not shown
    QCOMPARE(label->text(), first);
    label->showFrame(5.0, 200); // another scene: at once
    QVERIFY2(label->text().startsWith(QStringLiteral("draw 5.00 ms · 200 triangles")),
             qPrintable(label->text()));
    nowMs += ReadoutPace::kIntervalMs - 1;
    label->showFrame(6.0, 200); // not quite
    QVERIFY2(label->text().startsWith(QStringLiteral("draw 5.00 ms")), qPrintable(label->text()));
    nowMs += 1;
    label->showFrame(7.0, 200); // the interval is over
    QVERIFY2(label->text().startsWith(QStringLiteral("draw 7.00 ms")), qPrintable(label->text()));
}

void TestMainWindow::lightMarkersCanBeHidden()
{
    // Without markers every tinted pixel belongs to a lit object: the first
    // light is reddish, the second bluish, and each lights part of the scene.
    viewport()->drawing().setShowLightMarkers(false);
    const QImage unmarked = frame();
    saveArtifact(QStringLiteral("mainwindow-no-markers.png"), unmarked);
    const FrameColours stats = analyse(unmarked, toRgb(m_loaded.background));
    QVERIFY2(stats.foregroundFraction > 0.05,
             qPrintable(QString::number(stats.foregroundFraction)));
    QVERIFY2(stats.warmFraction > 0.005, qPrintable(QString::number(stats.warmFraction)));
    QVERIFY2(stats.coolFraction > 0.005, qPrintable(QString::number(stats.coolFraction)));

    // The default camera frames the objects and leaves the lights near or
    // outside the edge of the view; step back until they are in it.
    zoom(-7);
    const QImage withoutMarkers = frame();
    viewport()->drawing().setShowLightMarkers(true);
    const QImage withMarkers = frame();
    saveArtifact(QStringLiteral("mainwindow-markers.png"), withMarkers);
    QVERIFY(differingPixels(withMarkers, withoutMarkers) > 0);
}

void TestMainWindow::failedOpenKeepsCurrentScene_data()
{
    QTest::addColumn<QByteArray>("contents");
    QTest::addColumn<QString>("expectedError");
    QTest::newRow("malformed JSON")
        << QByteArray("{ \"mesh\": \"builtin:torus\", ") << QStringLiteral("JSON syntax error");
    QTest::newRow("missing mesh file")
        << QByteArray(R"({"mesh": "no-such-mesh.obj", "lights": [{"position": [1, 1, 1]}]})")
        << QStringLiteral("no-such-mesh.obj");
}

void TestMainWindow::failedOpenKeepsCurrentScene()
{
    QFETCH(QByteArray, contents);
    QFETCH(QString, expectedError);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("bad.json"));
    writeFile(path, contents);

    drag(Qt::LeftButton, {30, 0}); // the kept scene includes the moved camera
    const Scene before = viewport()->currentScene();
    const QString title = m_window->windowTitle();
    const QImage imageBefore = frame();

    const Result<> refusal = m_window->document()->openAndWait(path);
    QVERIFY(!refusal);
    QVERIFY2(refusal.error().contains(expectedError), qPrintable(refusal.error()));

    QCOMPARE(viewport()->currentScene(), before);
    QCOMPARE(m_window->document()->path(), defaultScenePathInSource());
    QCOMPARE(m_window->windowTitle(), title);
    QCOMPARE(differingPixels(frame(), imageBefore), 0);
}

void TestMainWindow::leftDragOrbitsCamera()
{
    const Camera original = viewport()->camera();
    const QImage before = frame();
    drag(Qt::LeftButton, {80, 40});
    const Camera moved = viewport()->camera();

    QVERIFY(moved.eye != original.eye);
    QCOMPARE(moved.target, original.target); // orbiting turns about the target
    QVERIFY(
        qAbs(glm::length(moved.eye - moved.target) - glm::length(original.eye - original.target))
        < 1e-9);
    QCOMPARE(moved.fovDeg, original.fovDeg);
    QCOMPARE(moved.nearPlane, original.nearPlane);
    QCOMPARE(moved.farPlane, original.farPlane);

    const QImage after = frame();
    saveArtifact(QStringLiteral("mainwindow-orbited.png"), after);
    QVERIFY(differingPixels(before, after) > before.width() * before.height() / 100);

    // However far the drag goes, the view stops short of looking straight
    // down, where lookAt would flip.
    drag(Qt::LeftButton, {0, 1500});
    const Camera top = viewport()->camera();
    const double cosFromUp = glm::dot(glm::normalize(top.eye - top.target), glm::normalize(top.up));
    QVERIFY2(cosFromUp > 0.99 && cosFromUp < 1.0, qPrintable(QString::number(cosFromUp, 'g', 17)));
    QVERIFY(analyse(frame(), toRgb(m_loaded.background)).foregroundFraction > 0.05);
}

void TestMainWindow::rightDragPansAndWheelZooms()
{
    const Camera original = viewport()->camera();
    drag(Qt::RightButton, {50, 0});
    const Camera panned = viewport()->camera();
    QVERIFY(panned.target != original.target);
    // Panning slides the camera without turning it.
    QVERIFY(glm::length((panned.eye - panned.target) - (original.eye - original.target)) < 1e-9);

    zoom(1);
    const Camera zoomed = viewport()->camera();
    QVERIFY(glm::length(zoomed.eye - zoomed.target) < glm::length(panned.eye - panned.target));
    QCOMPARE(zoomed.target, panned.target);
}

void TestMainWindow::resetRestoresOriginalCamera_data()
{
    QTest::addColumn<int>("key");
    QTest::newRow("R") << int(Qt::Key_R);
    QTest::newRow("Home") << int(Qt::Key_Home);
}

void TestMainWindow::resetRestoresOriginalCamera()
{
    QFETCH(int, key);
    const QImage originalFrame = frame();
    drag(Qt::LeftButton, {-120, 70});
    drag(Qt::MiddleButton, {25, -15});
    zoom(-2);
    QVERIFY(!(viewport()->camera() == m_shown.camera));

    viewport()->setFocus();
    QTest::keyClick(viewport(), Qt::Key(key));
    QCOMPARE(viewport()->camera(), m_shown.camera); // exactly, not approximately
    QCOMPARE(viewport()->currentScene(), m_shown);
    QCOMPARE(differingPixels(frame(), originalFrame), 0);
}

// The frames go to a native window of the view's own: what the window
// system delivers there (a real mouse, a key while it has focus) must move
// the camera as the widget's own events do.
void TestMainWindow::inputOnTheViewsOwnWindowReachesTheView()
{
    QWindow *window = viewport()->frames().window();
    QVERIFY(window && window->isExposed());
    QCOMPARE(window->size(), viewport()->size());
    const QImage originalFrame = frame();
    const QPoint start = viewport()->rect().center();
    m_window->menuBar()->setFocus(); // somewhere else first
    QTest::mousePress(window, Qt::LeftButton, Qt::NoModifier, start);
    QCOMPARE(m_window->focusWidget(), viewport()); // a click gives the view the keys
    for (int step = 1; step <= 4; ++step)
        QTest::mouseMove(window, start + QPoint(-30, 20) * step);
    QTest::mouseRelease(window, Qt::LeftButton, Qt::NoModifier, start + QPoint(-120, 80));
    QVERIFY(!(viewport()->camera() == m_shown.camera));
    QVERIFY(differingPixels(frame(), originalFrame) > 1000);

    QTest::keyClick(window, Qt::Key_R);
    QCOMPARE(viewport()->camera(), m_shown.camera);
    QCOMPARE(differingPixels(frame(), originalFrame), 0);
}

void TestMainWindow::saveThenReopenGivesEqualScene()
{
    drag(Qt::LeftButton, {45, -25});
    const Scene shown = viewport()->currentScene();
    QVERIFY(!(shown.camera == m_shown.camera)); // the saved camera must be the current one
    QVERIFY(!shown.camera.frameObjects);        // ... a shot the user composed, kept as it is

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("saved.json"));
    QVERIFY_OK(m_window->document()->save(path));
    QCOMPARE(m_window->document()->path(), path);
    QVERIFY(m_window->windowTitle().contains(QStringLiteral("saved.json")));

    const SceneLoadResult reread = loadSceneFile(path);
    QVERIFY2(reread.ok(), qPrintable(reread.error));
    QCOMPARE(withResolvedMeshes(*reread.scene), withResolvedMeshes(shown));

    // Reopened in the window it is the same scene, and "reset" now goes back
    // to the saved camera.
    QVERIFY(m_window->document()->openAndWait(defaultScenePathInSource()));
    QVERIFY_OK(m_window->document()->openAndWait(path));
    QCOMPARE(withResolvedMeshes(viewport()->currentScene()), withResolvedMeshes(shown));
    drag(Qt::LeftButton, {-60, 0});
    viewport()->resetCamera();
    QCOMPARE(viewport()->camera(), shown.camera);

    // A failed save reports why and changes nothing.
    const QString unwritable = dir.filePath(QStringLiteral("no-such-folder/saved.json"));
    const Result<> refusal = m_window->document()->save(unwritable);
    QVERIFY(!refusal);
    QVERIFY(!refusal.error().isEmpty());
    QCOMPARE(m_window->document()->path(), path);
}

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
