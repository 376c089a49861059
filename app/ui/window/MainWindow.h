#pragma once
#include "DefaultLayout.h"
#include "StartupOptions.h"

#include <QMainWindow>

class QLabel;

namespace phonglab {

class FileMenu;
class LiveCheck;
class LiveShaderController;
class LoadProgressWidget;
class PerformanceDock;
class RecentFiles;
class SceneDock;
class SceneDocument;
class SceneEditDockSet;
class ShaderDock;
class UniformsDock;
class Viewport;

// The editor window: the Viewport in the middle, the Shaders dock (live
// editing: LiveShaderController) right of it and the other docks as
// DefaultLayout puts them (View > Reset Layout puts them back), the menus
// (File: FileMenu, with the dialogs; View: ViewMenu; Help: HelpMenu) and a
// status bar with load progress, frame time (FrameStatsLabel) and the OpenGL
// renderer. What it shows is a SceneDocument: opened, saved, loaded and
// recovered there.
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    const StartupOptions &startupOptions() const { return m_options; }
    // Options default to what the environment says (StartupOptions.h).
    explicit MainWindow(QWidget *parent = nullptr,
                        const StartupOptions &options = StartupOptions::fromEnvironment());
    ~MainWindow() override;

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

    SceneDocument *document() const { return m_document; }
    Viewport *viewport() const { return m_viewport; }
    SceneDock *sceneDock() const { return m_sceneDock; }
    ShaderDock *shaderDock() const { return m_shaderDock; }
    UniformsDock *uniformsDock() const { return m_uniformsDock; }
    PerformanceDock *performanceDock() const { return m_performanceDock; }
    SceneEditDockSet *editDocks() const { return m_editDocks; }
    LiveShaderController *liveShaders() const { return m_liveShaders; }
    LiveCheck *liveCheck() const { return m_liveCheck; }
    RecentFiles *recentFiles() const { return m_recentFiles; }
    LoadProgressWidget *loadProgress() const { return m_loadProgress; }

protected:
    void closeEvent(QCloseEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    void createShaderDock();
    void createDocument();
    void createUniformsDock();
    void createPerformanceDock();
    void connectCheck();
    void createStatusBar();
    void connectLoading();
    void showRenderError(const QString &message);
    void refreshSceneDock();

    StartupOptions m_options; // first: the members below are built from it
    Viewport *m_viewport = nullptr;
    SceneDock *m_sceneDock = nullptr;
    SceneEditDockSet *m_editDocks = nullptr; // lights, material, object docks + undo stack
    ShaderDock *m_shaderDock = nullptr;
    UniformsDock *m_uniformsDock = nullptr;
    PerformanceDock *m_performanceDock = nullptr;
    LiveShaderController *m_liveShaders = nullptr;
    LiveCheck *m_liveCheck = nullptr;
    FileMenu *m_fileMenu = nullptr;
    RecentFiles *m_recentFiles = nullptr; // in the File menu
    SceneDocument *m_document = nullptr;
    LoadProgressWidget *m_loadProgress = nullptr;
    QLabel *m_rendererLabel = nullptr;
    bool m_defaultLayoutDue = true; // no saved layout: lay out the default when shown
    bool m_layingOut = false;       // the layout's own raising of tabs, not the user's
};

} // namespace phonglab
