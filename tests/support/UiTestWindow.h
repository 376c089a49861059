#pragma once
#include "core/scene/Scene.h"
#include "render/program/UniformSnapshot.h"
#include "ui/window/MainWindow.h"

#include <QByteArray>
#include <QImage>
#include <QObject>
#include <QSize>
#include <QString>
#include <QTemporaryDir>
#include <memory>

namespace phonglab {
class LiveShaderController;
class ShaderEditor;
class Viewport;
} // namespace phonglab

// What the UI tests (tests/ui) share: keeping the app away from the user's
// settings, caches and recovery files, and opening the editor window.
namespace phonglab::test {

// QSettings and recent files go to QStandardPaths' test folders, not the
// user's; windows get a single-sample default surface format, so a frame is
// exact (no multisampling) and can be compared pixel for pixel.
void useTestSettingsAndExactFrames();

// The private folders a UI test case points the app at. Keep it for the test
// case's lifetime: the folders go when it does.
class UiTestEnvironment
{
public:
    enum class Cache {
        PrivateWhenUnset, // a private PHONGLAB_CACHE_DIR unless one is set already (ctest sets one)
        AlwaysPrivate,    // a private PHONGLAB_CACHE_DIR even when one is set
    };

    // useTestSettingsAndExactFrames() and the mesh cache as `cache` says.
    void isolate(Cache cache = Cache::PrivateWhenUnset);

    // A new, empty PHONGLAB_RECOVERY_DIR (the previous one is removed), and
    // PHONGLAB_RECOVERY_ANSWER set to `answer` ("discard", "restore"), or
    // unset when `answer` is null so the window decides as it would for a user.
    void useFreshRecoveryDir(const char *answer);
    // The PHONGLAB_RECOVERY_DIR set by useFreshRecoveryDir(); empty before it.
    QString recoveryDir() const { return m_recoveryDir ? m_recoveryDir->path() : QString(); }

private:
    std::unique_ptr<QTemporaryDir> m_cacheDir;
    std::unique_ptr<QTemporaryDir> m_recoveryDir;
};

// Resizes `window` to `size`, shows it, and waits until it is exposed and its
// viewport has rendered a frame, which it is then ready to render again.
// Fails the current test with QTest's macros: check QTest::currentTestFailed()
// after it.
void showAndWaitForFrame(MainWindow &window, QSize size);

// A new MainWindow into `window` (the one there before is destroyed once the
// new one exists), with `scenePath` opened, then showAndWaitForFrame(). With
// `viewportSamples` the view multisamples as the app's does
// (useMultisamplingInViewOnly; kViewportSamples), else its frames are exact.
// Fails the current test with QTest's macros: check QTest::currentTestFailed()
// after it.
void openWindow(std::unique_ptr<MainWindow> &window, const QString &scenePath, QSize size,
                int viewportSamples = 0);

// Waits until the live shader controller has built and applied the text now
// in the editors; false when that takes longer than `timeoutMs`.
bool waitForApplied(const LiveShaderController &live, int timeoutMs);

// A second base of a UI test class (after QObject): the window under test,
// shortcuts into it, and the environment it runs in (which outlives it).
// The test's cleanup() resets m_window where each test wants a new one.
class UiTestWindow
{
protected:
    static constexpr int kBuildTimeoutMs = 10000; // debounce + compile + link + JIT, generously

    // test::openWindow() into m_window; check QTest::currentTestFailed() after it.
    void openWindow(const QString &scenePath, QSize size, int viewportSamples = 0)
    {
        test::openWindow(m_window, scenePath, size, viewportSamples);
    }

    Viewport *viewport() const;
    // The scene as Save would write it: with the scene's own camera until
    // the user moves it, not the one moved back to fit the view's present
    // shape (which a dock growing by a line of text changes).
    Scene savedScene() const;
    QImage frame() const; // the viewport's framebuffer
    // The values of the program the viewport draws with, read with its
    // context taken back first (it may be lent to the build thread).
    UniformSnapshot programSnapshot() const;
    LiveShaderController *live() const;
    ShaderEditor *fragmentEditor() const; // in the Shader dock
    // As a user would: selects `from` in the fragment editor and types `to`
    // over it (the build follows after the pause). Fails the current test
    // with QTest's macros when `from` is not there.
    void replaceInFragment(const QString &from, const QString &to) const;
    // Types the shipped fragment shader into the slide's equation taken
    // literally (no N·L guard on the highlight, the diffuse term clamped) and
    // waits until the live check has checked it by that equation; false when
    // it did not within `timeoutMs`. Check QTest::currentTestFailed() too.
    bool typeTheSlidesEquationAndCheck(int timeoutMs) const;
    bool waitForApplied(int timeoutMs = kBuildTimeoutMs) const
    {
        return test::waitForApplied(*live(), timeoutMs);
    }

    UiTestEnvironment m_env; // unused unless the test calls it
    std::unique_ptr<MainWindow> m_window;
};

// The base of a UI test class that opens a new window in its test cases:
// the window goes after each one, and the shader copies the app wrote for
// the user (ShaderFileSet::userFolder()) after the last.
class WindowPerTest : public QObject, public UiTestWindow
{
    Q_OBJECT

private slots:
    void cleanup() { m_window.reset(); }
    void cleanupTestCase();
};

} // namespace phonglab::test
