// Save then open gives an identical render: a scene saved with an edited
// shader and an orbited camera reopens with the same picture and the edited
// shader in the dock; a scene naming a missing shader opens with the shipped
// ones and an error; the window layout round-trips through QSettings.

#include "ResultChecks.h"
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "core/scene/SceneJson.h"
#include "ui/scene/SceneDock.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/shaders/ShaderFileSet.h"
#include "ui/uniforms/UniformsDock.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <memory>

using namespace phonglab;
using phonglab::test::sourcePath;

namespace {

QByteArray readFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

class TestSceneRoundTrip : public test::WindowPerTest
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();

    void saveThenOpenGivesIdenticalRender();
    void missingShaderFallsBackToShipped();
    void windowStateRoundTrips();

private:
    void openWindow();
    ShaderDock *dock() const { return m_window->shaderDock(); }
    void drag(QPoint by);

    QTemporaryDir m_sceneDir;
};

void TestSceneRoundTrip::initTestCase()
{
    m_env.isolate(test::UiTestEnvironment::Cache::AlwaysPrivate);
    QVERIFY(m_sceneDir.isValid());
    QDir(ShaderFileSet::userFolder()).removeRecursively(); // user copies from earlier runs
}

void TestSceneRoundTrip::init()
{
    m_env.useFreshRecoveryDir("discard");
}

void TestSceneRoundTrip::openWindow()
{
    UiTestWindow::openWindow(sourcePath(QStringLiteral("assets/scenes/default.json")), {900, 600});
}

void TestSceneRoundTrip::drag(QPoint by)
{
    const QPoint start = viewport()->rect().center();
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, start);
    for (int step = 1; step <= 4; ++step)
        QTest::mouseMove(viewport(), start + by * step / 4);
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, start + by);
}

void TestSceneRoundTrip::saveThenOpenGivesIdenticalRender()
{
    openWindow();
    // An edit to the fragment shader, typed as a user would.
    ShaderEditor *editor = fragmentEditor();
    QVERIFY(editor->findFirst(QStringLiteral("vec4(I"), false, true, false, false, true, 0, 0));
    int lineFrom = 0, indexFrom = 0, lineTo = 0, indexTo = 0;
    editor->getSelection(&lineFrom, &indexFrom, &lineTo, &indexTo);
    editor->setCursorPosition(lineTo, indexTo);
    editor->setFocus();
    QTest::keyClicks(editor, QStringLiteral(" * 0.5"));
    QVERIFY(waitForApplied());
    const QString edited = editor->text();
    QVERIFY(edited.contains(QStringLiteral("vec4(I * 0.5")));
    // And to the camera.
    drag({80, 40});
    const QImage before = frame(); // grabbing renders the view as it now is

    const QString scenePath = m_sceneDir.filePath(QStringLiteral("saved.json"));
    QString error;
    QVERIFY_OK(m_window->document()->save(scenePath));
    QVERIFY(!dock()->hasUnsavedChanges()); // the shader buffer was saved with the scene
    const QString fragmentFile = dock()->filePath(ShaderStage::Fragment);
    QCOMPARE(readFile(fragmentFile), edited.toUtf8());
    const SceneLoadResult written = loadSceneFile(scenePath);
    QVERIFY2(written.ok(), qPrintable(written.error));
    QCOMPARE(written.scene->resolveShaderPath(written.scene->fragmentShader),
             QFileInfo(fragmentFile).absoluteFilePath());
    QVERIFY(written.scene->vertexShader.isEmpty()); // still the shipped one: not written

    // Another scene, and the shipped shaders back in the dock.
    QVERIFY_OK(
        m_window->document()->openAndWait(sourcePath(QStringLiteral("assets/scenes/torus.json"))));
    live()->shading()->choose(ShadingMethod::Phong);
    QVERIFY(waitForApplied());
    QVERIFY(!fragmentEditor()->text().contains(QStringLiteral("vec4(I * 0.5")));
    QVERIFY(frame() != before);

    QVERIFY_OK(m_window->document()->openAndWait(scenePath));
    QVERIFY(m_window->document()->lastShaderError().isEmpty());
    QCOMPARE(fragmentEditor()->text(), edited);
    QCOMPARE(QFileInfo(dock()->filePath(ShaderStage::Fragment)).absoluteFilePath(),
             QFileInfo(fragmentFile).absoluteFilePath());
    QVERIFY(waitForApplied());
    const QImage after = frame();
    QCOMPARE(after.size(), before.size());
    QVERIFY2(after == before, "the reopened scene renders differently");
}

void TestSceneRoundTrip::missingShaderFallsBackToShipped()
{
    openWindow();
    const QByteArray shipped = fragmentEditor()->text().toUtf8();
    const QImage shippedFrame = frame();
    const QString scenePath = m_sceneDir.filePath(QStringLiteral("missing.json"));
    {
        QFile file(scenePath);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"mesh": "builtin:sphere", "shading": "phong",
                      "shaders": {"fragment": "nowhere/gone.frag"}})");
    }
    QString error;
    QVERIFY_OK(m_window->document()->openAndWait(scenePath));
    QVERIFY2(m_window->document()->lastShaderError().contains(QStringLiteral("shaders.fragment")),
             qPrintable(m_window->document()->lastShaderError()));
    QVERIFY(m_window->document()->lastShaderError().contains(QStringLiteral("gone.frag")));
    QCOMPARE(fragmentEditor()->text().toUtf8(), shipped);
    QVERIFY(dock()->files()->isShipped(dock()->filePath(ShaderStage::Fragment)));
    QVERIFY(waitForApplied());
    QVERIFY(!frame().isNull());
    Q_UNUSED(shippedFrame);
}

void TestSceneRoundTrip::windowStateRoundTrips()
{
    QSettings().remove(QStringLiteral("window"));
    openWindow();
    QVERIFY(!m_window->restoreWindowSettings()); // nothing stored yet
    QVERIFY(m_window->uniformsDock()->toggleViewAction()->isChecked());
    m_window->uniformsDock()->hide();
    QVERIFY(m_window->shaderDock()->toggleViewAction()->isChecked());
    m_window->saveWindowSettings();
    const bool sceneDockShown = m_window->sceneDock()->toggleViewAction()->isChecked();
    m_window.reset();

    MainWindow restored;
    QVERIFY(restored.restoreWindowSettings());
    restored.show();
    QVERIFY(QTest::qWaitForWindowExposed(&restored));
    QVERIFY(!restored.uniformsDock()->toggleViewAction()->isChecked());
    QVERIFY(restored.shaderDock()->toggleViewAction()->isChecked());
    QCOMPARE(restored.sceneDock()->toggleViewAction()->isChecked(), sceneDockShown);
    QSettings().remove(QStringLiteral("window"));
}

QTEST_MAIN(TestSceneRoundTrip)
#include "tst_sceneroundtrip.moc"
