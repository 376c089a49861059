// Opening meshes in the editor window, on a real GL context (Mesa llvmpipe
// under Xvfb): meshes load in the background while the window keeps
// running, fit into the view, list their statistics in the Scene dock, take
// other normals from it, survive save / reopen, and arrive by drag and drop.
// Broken and unsupported files, and cancelling, leave the scene alone.

#include "ImportChildren.h"
#include "PixelDiff.h"
#include "ResultChecks.h"
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "core/scene/SceneJson.h"
#include "mesh/loading/MeshLoader.h"
#include "ui/scene/MeshPlacement.h"
#include "ui/scene/MeshStatsText.h"
#include "ui/scene/NormalsEditor.h"
#include "ui/scene/SceneDock.h"
#include "ui/scene/SceneLoadJob.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/LoadProgressWidget.h"
#include "ui/window/MainWindow.h"
#include "ui/window/RecentFiles.h"
#include "ui/window/SceneDocument.h"
#include "ui/window/WindowImage.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QThreadPool>
#include <QTimer>
#include <QToolButton>
#include <QTreeWidget>
#include <algorithm>
#include <cmath>
#include <memory>

using namespace phonglab;
using namespace phonglab::test;
using phonglab::test::sourcePath;

namespace {

constexpr int kLoadTimeoutMs = 120000;  // llvmpipe and a debug build can be slow
constexpr int kBackgroundTolerance = 6; // 8-bit steps, per channel
constexpr int kLargeGridSide =
    710; // 2 · 709² ≈ 1M triangles: loads for a good fraction of a second
constexpr int kTickIntervalMs = 10;

QString treePath()
{
    return sourcePath(QStringLiteral("assets/meshes/tree.obj"));
}
QString cloudPath()
{
    return sourcePath(QStringLiteral("assets/meshes/cloud.obj"));
}

double foregroundFraction(const QImage &frame, const glm::dvec3 &background)
{
    const QRgb bg =
        qRgb(qRound(background.r * 255), qRound(background.g * 255), qRound(background.b * 255));
    const QImage image = frame.convertToFormat(QImage::Format_RGB32);
    qint64 foreground = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            foreground += differsFrom(image.pixel(x, y), bg, kBackgroundTolerance);
    return double(foreground) / (double(image.width()) * image.height());
}

void writeFile(const QString &path, const QByteArray &contents)
{
    QFile file(path);
    QVERIFY2(file.open(QIODevice::WriteOnly), qPrintable(file.errorString()));
    QCOMPARE(file.write(contents), contents.size());
}

// A wavy height field: open, smooth, no normals in the file.
QByteArray largeGridObj(int side)
{
    QByteArray obj;
    obj.reserve(side * side * 60);
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            const double x = double(i) / (side - 1) * 2.0 - 1.0,
                         z = double(j) / (side - 1) * 2.0 - 1.0;
            obj += "v " + QByteArray::number(x) + ' '
                + QByteArray::number(0.1 * std::sin(6 * x) * std::cos(6 * z)) + ' '
                + QByteArray::number(z) + '\n';
        }
    for (int i = 0; i + 1 < side; ++i)
        for (int j = 0; j + 1 < side; ++j) {
            const QByteArray a = QByteArray::number(i * side + j + 1),
                             b = QByteArray::number(i * side + j + 2);
            const QByteArray c = QByteArray::number((i + 1) * side + j + 1),
                             d = QByteArray::number((i + 1) * side + j + 2);
            obj += "f " + a + ' ' + b + ' ' + d + "\nf " + a + ' ' + d + ' ' + c + '\n';
        }
    return obj;
}

// The value column of field `name` under the dock's row for object `index`.
QString dockField(SceneDock *dock, int index, const QString &name)
{
    const QTreeWidgetItem *object = dock->objectTree()->topLevelItem(index);
    for (int i = 0; object && i < object->childCount(); ++i)
        if (object->child(i)->text(0) == name)
            return object->child(i)->text(1);
    return {};
}

} // namespace

class TestMeshLoading : public test::WindowPerTest
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();

    void openedMeshIsDrawnFittedAndListed();
    void brokenMeshFileKeepsScene_data();
    void brokenMeshFileKeepsScene();
    void unsupportedFileIsRefused();
    void staysResponsiveWhileLoading();
    void cancelKeepsScene();
    void hangingReaderIsStoppedAndSceneKept();
    void cancelEndsTheImportChild();
    void closingWhileLoading();
    void flatNormalsFromTheDock();
    void normalsSurviveSaveAndReopen();
    void droppedFilesOpenSideBySide();
    void meshOpenedBeforeFirstShow();
    void recentFilesRememberAndForget();
    void builtinShapesHaveNoNormalsControl();
    void warningsAreListed();

private:
    SceneDock *dock() const { return m_window->sceneDock(); }
    // Starts opening `paths` and waits for the load's outcome; true when it loaded.
    bool openAndWait(const QStringList &paths);
    bool waitForLoad(const std::function<void()> &start);
    QMessageBox *visibleMessageBox() const;
    // Drags `paths` onto the viewport and drops them there; true when accepted.
    bool dropFiles(const QStringList &paths);
    void saveArtifact(const QString &name, const QImage &image) const;

    QTemporaryDir m_dir;
    QString m_largeObj;
    Scene m_default;
    QString m_lastError;
};

void TestMeshLoading::initTestCase()
{
    // Recent files go to a throwaway settings folder, not the user's.
    test::useTestSettingsAndExactFrames();
    QVERIFY(m_dir.isValid());
    // A fresh mesh cache: the first load of every file here really parses it.
    qputenv("PHONGLAB_CACHE_DIR", QFile::encodeName(m_dir.filePath(QStringLiteral("cache"))));
    m_largeObj = m_dir.filePath(QStringLiteral("large_grid.obj"));
    writeFile(m_largeObj, largeGridObj(kLargeGridSide));
    const SceneLoadResult loaded =
        loadSceneFile(sourcePath(QStringLiteral("assets/scenes/default.json")));
    QVERIFY2(loaded.ok(), qPrintable(loaded.error));
    m_default = *loaded.scene;
}

void TestMeshLoading::init()
{
    m_window = std::make_unique<MainWindow>();
    m_window->recentFiles()->clear();
    QString error;
    QVERIFY_OK(m_window->document()->openAndWait(
        sourcePath(QStringLiteral("assets/scenes/default.json"))));
    test::showAndWaitForFrame(*m_window, {1000, 640});
}

bool TestMeshLoading::waitForLoad(const std::function<void()> &start)
{
    SceneLoadJob *job = m_window->document()->loadJob();
    QSignalSpy loaded(job, &SceneLoadJob::loaded);
    QSignalSpy failed(job, &SceneLoadJob::failed);
    QSignalSpy cancelled(job, &SceneLoadJob::cancelled);
    start();
    // Requests from the dock arrive queued: first the load starts (or ends at once) ...
    const bool started = QTest::qWaitFor(
        [&] { return job->isRunning() || !loaded.isEmpty() || !failed.isEmpty(); }, 1000);
    // ... then it ends.
    const bool ended = QTest::qWaitFor([&] { return !job->isRunning(); }, kLoadTimeoutMs);
    if (!started || !ended)
        qWarning("the load %s", !started ? "never started" : "did not end in time");
    m_lastError = failed.isEmpty() ? QString() : failed.last().at(1).toString();
    return !loaded.isEmpty() && failed.isEmpty() && !job->isRunning();
}

bool TestMeshLoading::openAndWait(const QStringList &paths)
{
    return waitForLoad([&] {
        if (const Result<> opened = m_window->document()->openFiles(paths); !opened)
            m_lastError = opened.error();
    });
}

QMessageBox *TestMeshLoading::visibleMessageBox() const
{
    for (QMessageBox *box : m_window->findChildren<QMessageBox *>())
        if (box->isVisible())
            return box;
    return nullptr;
}

bool TestMeshLoading::dropFiles(const QStringList &paths)
{
    QMimeData mime;
    QList<QUrl> urls;
    for (const QString &path : paths)
        urls << QUrl::fromLocalFile(path);
    mime.setUrls(urls);
    const QPoint centre = viewport()->rect().center();
    // Qt delivers the drop to the widget that accepted the drag's entry.
    QDragEnterEvent enter(centre, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(viewport(), &enter);
    if (!enter.isAccepted())
        return false;
    QDropEvent drop(QPointF(centre), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(viewport(), &drop);
    return drop.isAccepted();
}

void TestMeshLoading::saveArtifact(const QString &name, const QImage &image) const
{
    const QString dir = qEnvironmentVariable("PHONGLAB_TEST_ARTIFACTS");
    if (!dir.isEmpty() && QDir().mkpath(dir))
        image.save(QDir(dir).filePath(name));
}

void TestMeshLoading::openedMeshIsDrawnFittedAndListed()
{
    const Camera camera = viewport()->camera();
    QVERIFY2(openAndWait({treePath()}), qPrintable(m_lastError));

    const Scene scene = viewport()->currentScene();
    QCOMPARE(scene.objects.size(), std::size_t(1));
    QCOMPARE(scene.objects[0].mesh, QFileInfo(treePath()).absoluteFilePath());
    QCOMPARE(scene.camera, camera); // camera, lights and material are kept
    QCOMPARE(scene.lights, m_default.lights);
    QCOMPARE(scene.objects[0].material, m_default.objects[0].material);
    QVERIFY(m_window->windowTitle().contains(QStringLiteral("tree.obj")));

    // Fitted: largest extent 2, bounds centred on the origin.
    const MeshLoadResult reference = loadMesh(treePath());
    QVERIFY2(reference.ok(), qPrintable(reference.error));
    const MeshStats &stats = reference.stats;
    const Transform &t = scene.objects[0].transform;
    const glm::dvec3 lo = t.translate + t.scale * glm::dvec3(stats.boundsMin);
    const glm::dvec3 hi = t.translate + t.scale * glm::dvec3(stats.boundsMax);
    QVERIFY(qAbs(std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) - kFittedMeshSize) < 1e-6);
    QVERIFY(glm::length(lo + hi) < 1e-6);

    const QImage image = frame();
    saveArtifact(QStringLiteral("meshloading-tree.png"), image);
    saveArtifact(QStringLiteral("meshloading-window.png"), windowImage(*m_window));
    // A slender tree in a view narrower than tall: a few percent of it.
    QVERIFY2(foregroundFraction(image, scene.background) > 0.02,
             qPrintable(QString::number(foregroundFraction(image, scene.background))));

    // The dock lists what loading found, as MeshStats reports it.
    QCOMPARE(dock()->objectTree()->topLevelItemCount(), 1);
    QCOMPARE(dock()->objectTree()->topLevelItem(0)->text(0), QStringLiteral("tree.obj"));
    QCOMPARE(dock()->objectTree()->topLevelItem(0)->toolTip(0),
             QDir::toNativeSeparators(scene.objects[0].mesh));
    QCOMPARE(dockField(dock(), 0, QStringLiteral("Vertices")), countText(stats.vertices));
    QCOMPARE(dockField(dock(), 0, QStringLiteral("Triangles")), countText(stats.triangles));
    QCOMPARE(dockField(dock(), 0, QStringLiteral("Split vertices")),
             countText(stats.splitVertices));
    QCOMPARE(dockField(dock(), 0, QStringLiteral("Normals")), normalsDescription(stats, false));
    QCOMPARE(dockField(dock(), 0, QStringLiteral("Bounds")), boundsDescription(stats));
    QVERIFY(!dockField(dock(), 0, QStringLiteral("Load time")).isEmpty());
    QVERIFY(dock()->normalsEditor()->isEnabled());
    QVERIFY(!m_window->loadProgress()->isVisible());
}

void TestMeshLoading::brokenMeshFileKeepsScene_data()
{
    QTest::addColumn<bool>("exists");
    QTest::newRow("missing file") << false;
    QTest::newRow("random bytes") << true;
}

void TestMeshLoading::brokenMeshFileKeepsScene()
{
    QFETCH(bool, exists);
    const QString path = m_dir.filePath(QStringLiteral("x.obj"));
    QFile::remove(path);
    if (exists) {
        QByteArray garbage(64 * 1024, Qt::Uninitialized);
        QRandomGenerator generator(20240611);
        for (char &c : garbage)
            c = char(generator.bounded(256));
        writeFile(path, garbage);
    }
    const Scene before = viewport()->currentScene();
    const QString title = m_window->windowTitle();
    const QImage imageBefore = frame();

    QVERIFY(!openAndWait({path}));
    QVERIFY(!m_lastError.isEmpty());
    QCOMPARE(viewport()->currentScene(), before);
    QCOMPARE(m_window->windowTitle(), title);
    QCOMPARE(differingPixels(frame(), imageBefore), 0);
    // Reported in the status bar and in a message box.
    QVERIFY2(m_window->statusBar()->currentMessage().contains(QStringLiteral("x.obj")),
             qPrintable(m_window->statusBar()->currentMessage()));
    QMessageBox *box = visibleMessageBox();
    QVERIFY(box);
    QVERIFY2(box->text().contains(QStringLiteral("x.obj"))
                 && box->text().contains(m_lastError.section(u'\n', 0, 0)),
             qPrintable(box->text()));
    QVERIFY(!m_window->recentFiles()->files().contains(QFileInfo(path).absoluteFilePath()));
}

void TestMeshLoading::unsupportedFileIsRefused()
{
    const QString path = m_dir.filePath(QStringLiteral("notes.txt"));
    writeFile(path, "not a mesh");
    const Scene before = viewport()->currentScene();
    QSignalSpy started(m_window->document()->loadJob(), &SceneLoadJob::started);

    const Result<> notAMesh = m_window->document()->openFiles({path});
    QVERIFY(!notAMesh);
    QVERIFY2(notAMesh.error().contains(QStringLiteral("notes.txt"))
                 && notAMesh.error().contains(QStringLiteral(".obj")),
             qPrintable(notAMesh.error()));
    // A scene goes on its own, not mixed with meshes.
    const Result<> mixed = m_window->document()->openFiles(
        {treePath(), sourcePath(QStringLiteral("assets/scenes/default.json"))});
    QVERIFY(!mixed);
    QVERIFY2(mixed.error().contains(QStringLiteral("scene")), qPrintable(mixed.error()));
    QCOMPARE(started.count(), 0);
    QCOMPARE(viewport()->currentScene(), before);
}

void TestMeshLoading::staysResponsiveWhileLoading()
{
    // A timer on the GUI thread keeps ticking while the mesh loads, and the
    // old scene keeps being drawn. A load on the GUI thread would let no
    // tick through while it runs.
    qint64 ticks = 0, longestGapMs = 0;
    QElapsedTimer sinceTick;
    QTimer ticker;
    ticker.setInterval(kTickIntervalMs);
    connect(&ticker, &QTimer::timeout, this, [&] {
        longestGapMs = std::max(longestGapMs, sinceTick.restart());
        ticks += m_window->document()->loadJob()->isRunning();
    });
    bool progressShown = false;
    const qint64 framesBefore = viewport()->frames().frameStats().rendered;
    QSignalSpy progress(m_window->document()->loadJob(), &SceneLoadJob::progressChanged);
    QElapsedTimer loadTime;
    const bool ok = waitForLoad([&] {
        QString error;
        QVERIFY_OK(m_window->document()->openFiles({m_largeObj}));
        progressShown = m_window->loadProgress()->progressBar()->isVisible();
        QVERIFY(m_window->loadProgress()->isVisible());
        viewport()->frames().requestFrame(); // a frame of the old scene while loading
        saveArtifact(QStringLiteral("meshloading-loading.png"), windowImage(*m_window));
        loadTime.start();
        sinceTick.start();
        ticker.start();
    });
    ticker.stop();
    const qint64 loadMs = loadTime.elapsed();
    QVERIFY2(ok, qPrintable(m_lastError));
    qInfo("large mesh loaded in %lld ms; %lld ticks, longest gap %lld ms, %lld progress reports",
          loadMs, ticks, longestGapMs, qint64(progress.count()));
    QVERIFY(progressShown);
    QVERIFY(!m_window->loadProgress()->isVisible());
    QVERIFY(ticks >= 3);
    QVERIFY(viewport()->frames().frameStats().rendered > framesBefore);
    QCOMPARE(viewport()
                 ->meshInfo()
                 .value(meshKey(viewport()->currentScene(), viewport()->currentScene().objects[0]))
                 .stats.triangles,
             qint64(2) * (kLargeGridSide - 1) * (kLargeGridSide - 1));
}

void TestMeshLoading::cancelKeepsScene()
{
    const Scene before = viewport()->currentScene();
    SceneLoadJob *job = m_window->document()->loadJob();
    QSignalSpy loaded(job, &SceneLoadJob::loaded);
    QSignalSpy cancelled(job, &SceneLoadJob::cancelled);
    QString error;
    QVERIFY_OK(m_window->document()->openFiles({m_largeObj}));
    QVERIFY(m_window->loadProgress()->isVisible());
    QTest::mouseClick(m_window->loadProgress()->cancelButton(), Qt::LeftButton);

    QCOMPARE(cancelled.count(), 1);
    QVERIFY(!job->isRunning());
    QVERIFY(!m_window->loadProgress()->isVisible());
    // Whatever the abandoned worker does when it ends must not show: let it
    // end, and deliver what it queued.
    QVERIFY(QThreadPool::globalInstance()->waitForDone(kLoadTimeoutMs));
    QCoreApplication::processEvents();
    QCOMPARE(loaded.count(), 0);
    QCOMPARE(viewport()->currentScene(), before);
    QVERIFY(!visibleMessageBox()); // cancelling is not an error
    QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("cancelled")));
}

void TestMeshLoading::hangingReaderIsStoppedAndSceneKept()
{
    // Any reader bug that loops: the child is stopped at its time limit,
    // the user is told, and the scene (and anything unsaved) stays.
    const QString path = m_dir.filePath(QStringLiteral("hangs.obj"));
    QFile::copy(sourcePath(QStringLiteral("assets/meshes/tree.obj")), path);
    const Scene before = viewport()->currentScene();
    qputenv("PHONGLAB_IMPORT_FAULT", "hang");
    qputenv("PHONGLAB_IMPORT_TIMEOUT_S", "1");
    const bool loaded = openAndWait({path});
    qunsetenv("PHONGLAB_IMPORT_FAULT");
    qunsetenv("PHONGLAB_IMPORT_TIMEOUT_S");
    QVERIFY(!loaded);
    QVERIFY2(m_lastError.contains(QStringLiteral("stopped answering after 1 s")),
             qPrintable(m_lastError));
    QCOMPARE(viewport()->currentScene(), before);
    QVERIFY(importChildren().isEmpty());
    QMessageBox *box = visibleMessageBox();
    QVERIFY(box);
    QVERIFY(box->text().contains(QStringLiteral("hangs.obj"))
            || box->informativeText().contains(QStringLiteral("hangs.obj"))
            || box->detailedText().contains(QStringLiteral("hangs.obj")));
    box->close();
}

void TestMeshLoading::cancelEndsTheImportChild()
{
    const QString path = m_dir.filePath(QStringLiteral("never_ends.obj"));
    QFile::copy(sourcePath(QStringLiteral("assets/meshes/tree.obj")), path);
    const Scene before = viewport()->currentScene();
    qputenv("PHONGLAB_IMPORT_FAULT", "hang");
    QString error;
    QVERIFY_OK(m_window->document()->openFiles({path}));
    QTRY_VERIFY_WITH_TIMEOUT(!importChildren().isEmpty(), 5000);
    qunsetenv("PHONGLAB_IMPORT_FAULT");
    QElapsedTimer clock;
    clock.start();
    QTest::mouseClick(m_window->loadProgress()->cancelButton(), Qt::LeftButton);
    const qint64 toIdleMs = clock.elapsed(); // the window takes input again
    QVERIFY(!m_window->document()->loadJob()->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(importChildren().isEmpty(), 2000);
    const qint64 childGoneMs = clock.elapsed();
    qInfo("Cancel: window idle after %lld ms, import child gone after %lld ms", toIdleMs,
          childGoneMs);
    QCOMPARE(viewport()->currentScene(), before);
    QVERIFY(!visibleMessageBox());
}

void TestMeshLoading::closingWhileLoading()
{
    // The window goes while its worker runs: the worker is stopped and
    // nothing it finishes reaches the destroyed window.
    QString error;
    QVERIFY_OK(m_window->document()->openFiles({m_largeObj}));
    QVERIFY(m_window->document()->loadJob()->isRunning());
    QElapsedTimer timer;
    timer.start();
    m_window.reset();
    qInfo("window closed %lld ms into a load", timer.elapsed());
    // The abandoned worker ends with nothing left to report to.
    QVERIFY(QThreadPool::globalInstance()->waitForDone(kLoadTimeoutMs));
    QCoreApplication::processEvents();
}

void TestMeshLoading::flatNormalsFromTheDock()
{
    QVERIFY2(openAndWait({treePath()}), qPrintable(m_lastError));
    QCOMPARE(dockField(dock(), 0, QStringLiteral("Normals")), QStringLiteral("from file"));
    const QImage smooth = frame();

    dock()->selectObject(0);
    auto *method = dock()->normalsEditor()->findChild<QComboBox *>(QStringLiteral("normalMethod"));
    QVERIFY(method);
    QCOMPARE(method->currentText(), QStringLiteral("auto"));
    const int flat = method->findText(QStringLiteral("flat"));
    QVERIFY(flat > 0);
    // As the user would: keyboard selection emits activated().
    QVERIFY(waitForLoad([&] {
        for (int i = method->currentIndex(); i < flat; ++i)
            QTest::keyClick(method, Qt::Key_Down);
    }));

    const Scene scene = viewport()->currentScene();
    QCOMPARE(scene.objects[0].normals.method, NormalMethod::Flat);
    const MeshStats stats = viewport()->meshInfo().value(meshKey(scene, scene.objects[0])).stats;
    QVERIFY(!stats.normalsFromFile);
    QCOMPARE(stats.normalMethod, NormalMethod::Flat);
    QCOMPARE(dockField(dock(), 0, QStringLiteral("Normals")), QStringLiteral("computed (flat)"));
    QCOMPARE(dockField(dock(), 0, QStringLiteral("Vertices")), countText(stats.vertices));
    QCOMPARE(method->currentText(), QStringLiteral("flat"));

    const QImage faceted = frame();
    saveArtifact(QStringLiteral("meshloading-tree-flat.png"), faceted);
    saveArtifact(QStringLiteral("meshloading-window-flat.png"), windowImage(*m_window));
    QVERIFY2(differingPixels(smooth, faceted) > smooth.width() * smooth.height() / 200,
             qPrintable(QString::number(differingPixels(smooth, faceted))));
}

void TestMeshLoading::normalsSurviveSaveAndReopen()
{
    QVERIFY2(openAndWait({treePath()}), qPrintable(m_lastError));
    auto *crease = dock()->normalsEditor()->findChild<QCheckBox *>(QStringLiteral("creaseEnabled"));
    auto *angle = dock()->normalsEditor()->findChild<QSpinBox *>(QStringLiteral("creaseAngle"));
    QVERIFY(crease && angle);
    QVERIFY(waitForLoad([&] {
        m_window->document()->changeNormals(0, {NormalMethod::AreaWeighted, std::nullopt});
    }));
    QVERIFY(waitForLoad([&] { crease->click(); }));
    QVERIFY(waitForLoad([&] { angle->setValue(40); }));

    const NormalOptions expected{NormalMethod::AreaWeighted, 40.0};
    QCOMPARE(viewport()->currentScene().objects[0].normals, expected);
    QCOMPARE(dockField(dock(), 0, QStringLiteral("Normals")),
             QStringLiteral("computed (area, crease 40°)"));

    const QString path = m_dir.filePath(QStringLiteral("tree-scene.json"));
    QString error;
    QVERIFY_OK(m_window->document()->save(path));
    const SceneLoadResult saved = loadSceneFile(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error));
    QCOMPARE(saved.scene->objects[0].normals, expected);
    QCOMPARE(saved.scene->objects[0].transform, viewport()->currentScene().objects[0].transform);

    QVERIFY(m_window->document()->openAndWait(
        sourcePath(QStringLiteral("assets/scenes/default.json"))));
    QVERIFY2(openAndWait({path}), qPrintable(m_lastError));
    QCOMPARE(m_window->document()->path(), path);
    QCOMPARE(viewport()->currentScene().objects[0].normals, expected);
    QCOMPARE(dock()->normalsEditor()->options(), expected);
    QVERIFY(crease->isChecked());
    QCOMPARE(angle->value(), 40);
}

void TestMeshLoading::droppedFilesOpenSideBySide()
{
    QVERIFY(waitForLoad([&] { QVERIFY(dropFiles({treePath(), cloudPath()})); }));

    const Scene scene = viewport()->currentScene();
    QCOMPARE(scene.objects.size(), std::size_t(2));
    QCOMPARE(QFileInfo(scene.objects[0].mesh).fileName(), QStringLiteral("tree.obj"));
    QCOMPARE(QFileInfo(scene.objects[1].mesh).fileName(), QStringLiteral("cloud.obj"));
    // Each fitted, centred at x = ∓spacing/2.
    for (int i = 0; i < 2; ++i) {
        const MeshStats stats =
            viewport()->meshInfo().value(meshKey(scene, scene.objects[i])).stats;
        const Transform &t = scene.objects[i].transform;
        const glm::dvec3 centreWorld = t.translate
            + t.scale * (glm::dvec3(stats.boundsMin) + glm::dvec3(stats.boundsMax)) * 0.5;
        QVERIFY(glm::length(centreWorld - glm::dvec3((i - 0.5) * kSideBySideSpacing, 0, 0)) < 1e-6);
    }
    QCOMPARE(dock()->objectTree()->topLevelItemCount(), 2);
    saveArtifact(QStringLiteral("meshloading-dropped.png"), windowImage(*m_window));
    QVERIFY(foregroundFraction(frame(), scene.background) > 0.05);

    // An unsupported file dropped: explained, nothing changes.
    const QString text = m_dir.filePath(QStringLiteral("readme.txt"));
    writeFile(text, "hello");
    QVERIFY(dropFiles({text}));
    QTRY_VERIFY(visibleMessageBox());
    QVERIFY2(visibleMessageBox()->text().contains(QStringLiteral("readme.txt")),
             qPrintable(visibleMessageBox()->text()));
    QVERIFY(!m_window->document()->loadJob()->isRunning());
    QCOMPARE(viewport()->currentScene(), scene);

    // A dropped scene file opens as the scene.
    const QString torus = sourcePath(QStringLiteral("assets/scenes/torus.json"));
    QVERIFY(waitForLoad([&] { QVERIFY(dropFiles({torus})); }));
    QCOMPARE(m_window->document()->path(), torus);
    QCOMPARE(savedScene(), *loadSceneFile(torus).scene);
}

void TestMeshLoading::meshOpenedBeforeFirstShow()
{
    // The meshes wait in the viewport until GL is up, then show.
    m_window = std::make_unique<MainWindow>();
    QString error;
    QVERIFY_OK(m_window->document()->openAndWait(
        sourcePath(QStringLiteral("assets/scenes/default.json"))));
    QVERIFY2(openAndWait({treePath()}), qPrintable(m_lastError));
    QCOMPARE(dock()->objectTree()->topLevelItemCount(), 1);
    QVERIFY(!dockField(dock(), 0, QStringLiteral("Triangles")).isEmpty());
    test::showAndWaitForFrame(*m_window, {800, 600});
    if (QTest::currentTestFailed())
        return;
    QVERIFY(foregroundFraction(frame(), viewport()->currentScene().background) > 0.05);
}

void TestMeshLoading::recentFilesRememberAndForget()
{
    QVERIFY2(openAndWait({treePath()}), qPrintable(m_lastError));
    QCOMPARE(m_window->recentFiles()->files(),
             QStringList{QFileInfo(treePath()).absoluteFilePath()});

    const QString doomed = m_dir.filePath(QStringLiteral("doomed.obj"));
    QVERIFY(QFile::copy(treePath(), doomed));
    QVERIFY2(openAndWait({doomed}), qPrintable(m_lastError));
    QCOMPARE(m_window->recentFiles()->files().first(), QFileInfo(doomed).absoluteFilePath());
    QVERIFY(QFile::remove(doomed));

    // Chosen from File → Recent: gone, so removed with a message.
    QMenu *recent = nullptr;
    for (QMenu *menu : m_window->findChildren<QMenu *>())
        if (menu->title() == QStringLiteral("&Recent"))
            recent = menu;
    QVERIFY(recent);
    emit recent->aboutToShow();
    QAction *entry = nullptr;
    for (QAction *action : recent->actions())
        if (action->text().endsWith(QStringLiteral("doomed.obj")))
            entry = action;
    QVERIFY(entry);
    const Scene before = viewport()->currentScene();
    entry->trigger();
    QTRY_VERIFY(visibleMessageBox());
    QVERIFY(visibleMessageBox()->text().contains(QStringLiteral("no longer exists")));
    QCOMPARE(m_window->recentFiles()->files(),
             QStringList{QFileInfo(treePath()).absoluteFilePath()});
    QCOMPARE(viewport()->currentScene(), before);

    m_window->recentFiles()->clear();
    QVERIFY(m_window->recentFiles()->files().isEmpty());
}

void TestMeshLoading::builtinShapesHaveNoNormalsControl()
{
    QString error;
    QVERIFY_OK(
        m_window->document()->openAndWait(sourcePath(QStringLiteral("assets/scenes/torus.json"))));
    QCOMPARE(dock()->objectTree()->topLevelItemCount(), 1);
    QCOMPARE(dock()->objectTree()->topLevelItem(0)->text(0), QStringLiteral("builtin:torus"));
    QCOMPARE(dockField(dock(), 0, QStringLiteral("Normals")), QStringLiteral("analytic (exact)"));
    QVERIFY(!dock()->normalsEditor()->isEnabled());
    QCOMPARE(dock()->normalsEditor()->toolTip(),
             QStringLiteral("builtin shapes have exact analytic normals"));
}

void TestMeshLoading::warningsAreListed()
{
    // A tetrahedron with two vertices no face uses and a face pointing past
    // the last vertex: loading repairs both and says so.
    const QString path = m_dir.filePath(QStringLiteral("repaired.obj"));
    writeFile(path,
              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 5 5 5\nv 6 6 6\n"
              "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 2 99\n");
    const MeshLoadResult reference = loadMesh(path);
    QVERIFY2(reference.ok(), qPrintable(reference.error));
    QVERIFY(!reference.warnings.isEmpty());
    QVERIFY2(openAndWait({path}), qPrintable(m_lastError));

    const QTreeWidgetItem *object = dock()->objectTree()->topLevelItem(0);
    QVERIFY(object);
    QVERIFY2(object->text(1).contains(QString::number(reference.warnings.size())),
             qPrintable(object->text(1)));
    QVERIFY(!object->icon(1).isNull());
    const QTreeWidgetItem *list = nullptr;
    for (int i = 0; i < object->childCount(); ++i)
        if (object->child(i)->text(0) == QStringLiteral("Warnings"))
            list = object->child(i);
    QVERIFY(list);
    QVERIFY(list->isExpanded()); // listed visibly, not folded away
    QStringList shown;
    for (int i = 0; i < list->childCount(); ++i) {
        shown << list->child(i)->text(0);
        QVERIFY(!list->child(i)->icon(0).isNull());
    }
    QCOMPARE(shown, reference.warnings);
    saveArtifact(QStringLiteral("meshloading-warnings.png"), windowImage(*m_window));
}

QTEST_MAIN(TestMeshLoading)
#include "tst_meshloading.moc"
