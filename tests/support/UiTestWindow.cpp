#include "UiTestWindow.h"

#include "ResultChecks.h"
#include "render/gl/GlFormat.h"
#include "ui/check/LiveCheck.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/shaders/ShaderFileSet.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/GuiMain.h"
#include "ui/window/MainWindow.h"

#include "ui/window/SceneDocument.h"
#include <QDir>

#include <QElapsedTimer>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTest>

namespace phonglab::test {

void useTestSettingsAndExactFrames()
{
    QStandardPaths::setTestModeEnabled(true);
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0)); // single-sample: exact frames
}

void UiTestEnvironment::isolate(Cache cache)
{
    useTestSettingsAndExactFrames();
    if (cache == Cache::AlwaysPrivate || qEnvironmentVariableIsEmpty("PHONGLAB_CACHE_DIR")) {
        m_cacheDir = std::make_unique<QTemporaryDir>();
        qputenv("PHONGLAB_CACHE_DIR", m_cacheDir->path().toUtf8());
    }
}

void UiTestEnvironment::useFreshRecoveryDir(const char *answer)
{
    m_recoveryDir = std::make_unique<QTemporaryDir>();
    qputenv("PHONGLAB_RECOVERY_DIR", m_recoveryDir->path().toUtf8());
    if (answer)
        qputenv("PHONGLAB_RECOVERY_ANSWER", answer);
    else
        qunsetenv("PHONGLAB_RECOVERY_ANSWER");
}

void showAndWaitForFrame(MainWindow &window, QSize size)
{
    window.resize(size);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_VERIFY(window.viewport()->frames().frameStats().rendered > 0);
    QVERIFY(window.viewport()->isRenderReady());
}

void openWindow(std::unique_ptr<MainWindow> &window, const QString &scenePath, QSize size,
                int viewportSamples)
{
    window = std::make_unique<MainWindow>();
    if (viewportSamples > 0)
        useMultisamplingInViewOnly(*window, viewportSamples);
    QString error;
    QVERIFY_OK(window->document()->openAndWait(scenePath));
    showAndWaitForFrame(*window, size);
}

bool waitForApplied(const LiveShaderController &live, int timeoutMs)
{
    return QTest::qWaitFor(
        [&] { return live.appliedHash() == live.currentHash() && !live.isBuilding(); }, timeoutMs);
}

Viewport *UiTestWindow::viewport() const
{
    return m_window->viewport();
}

Scene UiTestWindow::savedScene() const
{
    Scene scene = viewport()->currentScene();
    scene.camera = viewport()->cameraToSave();
    return scene;
}

QImage UiTestWindow::frame() const
{
    return viewport()->grabFramebuffer();
}

UniformSnapshot UiTestWindow::programSnapshot() const
{
    return viewport()->program().values();
}

LiveShaderController *UiTestWindow::live() const
{
    return m_window->liveShaders();
}

ShaderEditor *UiTestWindow::fragmentEditor() const
{
    return m_window->shaderDock()->editor(ShaderStage::Fragment);
}

void UiTestWindow::replaceInFragment(const QString &from, const QString &to) const
{
    ShaderEditor *editor = fragmentEditor();
    QVERIFY2(editor->findFirst(from, false, true, false, false, true, 0, 0), qPrintable(from));
    editor->setFocus();
    QTest::keyClicks(editor, to);
    QVERIFY(editor->text().contains(to));
}

bool UiTestWindow::typeTheSlidesEquationAndCheck(int timeoutMs) const
{
    replaceInFragment(QStringLiteral("if (NdotL <= 0.0)"), QStringLiteral("if (false)"));
    replaceInFragment(QStringLiteral("Id[i] * kd * NdotL"),
                      QStringLiteral("Id[i] * kd * max(0.0, NdotL)"));
    if (QTest::currentTestFailed())
        return false;
    const LiveCheck *check = m_window->liveCheck();
    return QTest::qWaitFor(
        [&] {
            return !check->isChecking() && check->lastResult()
                && check->lastResult()->report().equation == PhongEquation::Slide;
        },
        timeoutMs);
}

void WindowPerTest::cleanupTestCase()
{
    QDir(ShaderFileSet::userFolder()).removeRecursively();
}

} // namespace phonglab::test
