#pragma once
#include "DefaultLayout.h"
#include "StartupOptions.h"
#include "core/scene/NormalOptions.h"
#include "core/support/Result.h"
#include "core/scene/ShadingMethod.h"

#include <QMainWindow>

#include <memory>

class QAction;
class QLabel;

namespace phonglab {

struct Scene;

class FileMenu;
class LiveCheck;
class LiveShaderController;
class LoadProgressWidget;
class PerformanceDock;
class RecentFiles;
class SceneDock;
class SceneEditDockSet;
class SceneLoadJob;
class SceneShaderFiles;
class ShaderDock;
class UniformsDock;
class Viewport;

// The editor window: the Viewport in the middle, the Shaders dock (live
// editing: LiveShaderController) right of it and the other docks as
// DefaultLayout puts them (View > Reset Layout puts them back),
// the menus (File: FileMenu, with the dialogs; Help: HelpMenu) and a status
// bar with load progress, frame time (FrameStatsLabel) and the OpenGL
// renderer. It opens, saves and exports without dialogs; the scene's shader
// files go through SceneShaderFiles. At start it offers the shader edits a
// crashed session left behind (ShaderRecovery).
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    const StartupOptions &startupOptions() const { return m_options; }
    // Options default to what the environment says (StartupOptions.h).
    explicit MainWindow(QWidget *parent = nullptr,
                        const StartupOptions &options = StartupOptions::fromEnvironment());
    ~MainWindow() override;

    // Load / save without any dialog, on the calling thread (startup, tests);
    // false with a reason on failure. A failed open keeps the current scene;
    // saving writes the scene with the camera as currently orbited. Saving
    // first saves the Shaders dock's unsaved buffers, then writes the dock's
    // files as the scene's "shaders" when they are not the shipped ones;
    // opening a scene with "shaders" loads and builds those files (a missing
    // one: a warning, and the shading method's shipped shaders stay).
    Result<> openScene(const QString &path);
    Result<> saveScene(const QString &path);

    // What File → Open, File → Recent and dropping files do: one scene
    // (.json), or any number of meshes that replace the scene's objects, side
    // by side. Loads in the background and reports through loadJob(). False
    // with a reason, and nothing changes, when the files cannot be opened at
    // all (an unsupported type, a broken scene file).
    Result<> openFiles(const QStringList &paths);
    // A scene with a student's shaders in place of its own (issue 31, B):
    // `phonglab SCENE.json --vertex FILE --fragment FILE`, and the command
    // each row of a grading report carries. An empty path keeps the scene's
    // stage (or the shipped one). Loads in the background as openFiles().
    Result<> openSubmission(const QString &scenePath, const QString &vertexPath,
                            const QString &fragmentPath);
    // A program's two stages in the Shaders dock, built and checked live on
    // the current scene (File → Open Project: "index.html#vsSource"
    // locators). Unsaved edits are the caller's to confirm first.
    Result<> openShaders(const QString &vertexPath, const QString &fragmentPath);
    // Reloads object `objectIndex`'s mesh with other normals, in the background.
    void changeNormals(int objectIndex, const NormalOptions &options);
    // Shows every object at `detail` with `method` shading (Fit to budget),
    // loading the coarser meshes in the background.
    void applyModel(ShadingMethod method, double detail);

    // Window geometry and dock layout in QSettings ("window/geometry",
    // "window/state"): saved when the window closes, restored at start
    // (GuiMain; not in the constructor, so tests start from the default
    // layout). False when nothing usable was stored.
    void saveWindowSettings() const;
    bool restoreWindowSettings();
    // Every dock back where a new window has it, for the present size (View
    // > Reset Layout).
    void resetLayout();
    WindowDocks docks() const;

    // Renders the current view at `size` pixels and writes it as PNG.
    Result<> exportImage(const QString &path, const QSize &size);

    QString scenePath() const { return m_scenePath; }
    // Why the last opened scene's "shaders" could not be used; empty if they could.
    QString lastShaderError() const { return m_lastShaderError; }
    Viewport *viewport() const { return m_viewport; }
    SceneLoadJob *loadJob() const { return m_loadJob; }
    SceneDock *sceneDock() const { return m_sceneDock; }
    ShaderDock *shaderDock() const { return m_shaderDock; }
    UniformsDock *uniformsDock() const { return m_uniformsDock; }
    PerformanceDock *performanceDock() const { return m_performanceDock; }
    SceneEditDockSet *editDocks() const { return m_editDocks; }
    LiveShaderController *liveShaders() const { return m_liveShaders; }
    LiveCheck *liveCheck() const { return m_liveCheck; }
    RecentFiles *recentFiles() const { return m_recentFiles; }
    LoadProgressWidget *loadProgress() const { return m_loadProgress; }

private slots:
    void showRenderError(const QString &message);
    void showLoadFailure(const QString &label, const QString &error);
    void showLoadCancelled(const QString &label);
    void refreshSceneDock();

protected:
    void closeEvent(QCloseEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    void createShaderDock();
    void createUniformsDock();
    void createPerformanceDock();
    void typeTestTextAfterStart();
    void createFileMenu();
    void createViewMenu();
    void createStatusBar();
    void connectLoading();
    Result<> startSceneLoad(const QString &path, const QString &vertexPath = {},
                            const QString &fragmentPath = {});
    void openSceneShaders(const Scene &scene);
    void setScenePath(const QString &path, const QString &title = {});
    void warn(const QString &title, const QString &message);

    StartupOptions m_options; // first: the members below are built from it
    Viewport *m_viewport = nullptr;
    SceneLoadJob *m_loadJob = nullptr;
    SceneDock *m_sceneDock = nullptr;
    SceneEditDockSet *m_editDocks = nullptr; // lights, material, object docks + undo stack
    ShaderDock *m_shaderDock = nullptr;
    UniformsDock *m_uniformsDock = nullptr;
    PerformanceDock *m_performanceDock = nullptr;
    LiveShaderController *m_liveShaders = nullptr;
    std::unique_ptr<SceneShaderFiles> m_sceneShaderFiles;
    LiveCheck *m_liveCheck = nullptr;
    FileMenu *m_fileMenu = nullptr;
    RecentFiles *m_recentFiles = nullptr; // in the File menu
    LoadProgressWidget *m_loadProgress = nullptr;
    QAction *m_resetCameraAction = nullptr;
    QAction *m_lightMarkersAction = nullptr;
    QLabel *m_rendererLabel = nullptr;
    QString m_scenePath;
    QString m_lastShaderError;
    bool m_defaultLayoutDue = true; // no saved layout: lay out the default when shown
};

} // namespace phonglab
