#pragma once
#include "core/scene/NormalOptions.h"
#include "core/scene/ShadingMethod.h"
#include "core/support/Result.h"
#include "ui/shaders/ShaderRecovery.h"

#include <QObject>
#include <QStringList>

#include <memory>

class QMainWindow;
class QSize;

namespace phonglab {

struct Scene;

class LiveShaderController;
class RecentFiles;
class SceneLoadJob;
class SceneShaderFiles;
class ShaderDock;
class Viewport;

// The scene the window shows as a document: opening it (a scene file, mesh
// files, a student's submission, a project's shaders), saving it, exporting
// its picture, the loads that change it (other normals, a fit, auto detail)
// and the crash-recovery questions about its unsaved shaders. All without
// file dialogs (FileMenu puts those in front); what happens is said in the
// window's status bar, and a load that fails in a warning.
//
// A scene file opens one way, open(): parsed at once (a broken file is
// refused there and then), its meshes loaded in the background by the
// SceneLoadJob, then shown with its "shaders" in the Shaders dock
// (SceneShaderFiles). openAndWait() is the same, waited for.
class SceneDocument : public QObject
{
    Q_OBJECT

public:
    SceneDocument(QMainWindow *window, Viewport *viewport, ShaderDock *shaders,
                  LiveShaderController *liveShaders, RecentFiles *recentFiles);
    ~SceneDocument() override;

    // Opens the scene file at `path` in the background; a shader file given
    // here (or a project's "FILE#KEY" locator) takes the place of the
    // scene's own stage. False with a reason, and nothing changes, when the
    // file cannot be parsed. The load reports through loadJob(): a failed
    // one keeps the current scene and says why in a warning.
    Result<> open(const QString &path, const QString &vertexPath = {},
                  const QString &fragmentPath = {});
    // open(), then waits on this thread until the scene is shown (start-up,
    // tests, tools). A failure is returned, not shown, and the file is not
    // added to the recent files: nobody chose it.
    Result<> openAndWait(const QString &path);
    // What File → Open, File → Recent and dropping files do: one scene
    // (.json, through open()), or any number of meshes that replace the
    // scene's objects, side by side. False with a reason, and nothing
    // changes, when the files cannot be opened at all (an unsupported type,
    // a broken scene file).
    Result<> openFiles(const QStringList &paths);
    // A scene with a student's shaders in place of its own:
    // `phonglab SCENE.json --vertex FILE --fragment FILE`, and the command
    // each row of a grading report carries. An empty path keeps the scene's
    // stage (or the shipped one).
    Result<> openSubmission(const QString &scenePath, const QString &vertexPath,
                            const QString &fragmentPath);
    // A program's two stages in the Shaders dock, built and checked live on
    // the current scene (File → Open Project: "index.html#vsSource"
    // locators). Unsaved edits are the caller's to confirm first.
    Result<> openShaders(const QString &vertexPath, const QString &fragmentPath);
    // One shader (its stage by its suffix) or a vertex and a fragment
    // shader, in place of the editor's; the scene's explicit bindings go
    // with the shaders they were made for.
    Result<> openShaderFiles(const QStringList &paths);

    // Writes the scene with the camera as currently orbited. First saves the
    // Shaders dock's unsaved buffers, then names the dock's files as the
    // scene's "shaders" when they are not the shipped ones.
    Result<> save(const QString &path);
    // Renders the current view at `size` pixels and writes it as PNG.
    Result<> exportImage(const QString &path, const QSize &size);

    // Reloads object `objectIndex`'s mesh with other normals, in the background.
    void changeNormals(int objectIndex, const NormalOptions &options);
    // Shows every object at `detail` with `method` shading (Fit to budget),
    // loading the coarser meshes in the background.
    void applyFit(ShadingMethod method, double detail);
    // Every object to "detail": "auto", or back to full detail.
    void setAutoDetail(bool on);

    // At start: offers the shader edits a crashed session left behind
    // (ShaderRecovery), at once when `answer` is given (tests, scripts),
    // else once the window is up. With `testText`, the crash-recovery test's
    // hook: that text is typed into the fragment editor once GL is up, as an
    // edit, and journaled at once (the test then kills the process).
    void offerRecovery(ShaderRecovery::Answer answer, const QString &testText = {});
    // Before the window closes: unsaved shaders are offered for saving (a
    // clean exit forgets the recovery journal). False when the user cancels.
    bool confirmClose();

    // The scene file shown; empty for a scene that was never saved.
    QString path() const { return m_path; }
    // Why the last opened scene's "shaders" could not be used; empty if they could.
    QString lastShaderError() const { return m_lastShaderError; }
    SceneLoadJob *loadJob() const { return m_loadJob; }

signals:
    // A file was opened or saved there: the file dialogs start in its folder.
    void folderUsed(const QString &filePath);

private:
    // What open() remembers of a scene once it is shown.
    enum class Remember {
        InRecentFiles,
        Nothing
    };
    Result<> startLoading(const QString &path, const QString &vertexPath,
                          const QString &fragmentPath, Remember remember);
    void openSceneShaders(const Scene &scene);
    void setPath(const QString &path, const QString &title = {});
    void showLoadFailure(const QString &label, const QString &error);
    void showLoadCancelled(const QString &label);
    void askAboutRecovery(ShaderRecovery::Answer answer);
    void typeAfterStart(const QString &text);
    void showStatus(const QString &message);

    QMainWindow *m_window = nullptr;
    Viewport *m_viewport = nullptr;
    ShaderDock *m_shaders = nullptr;
    LiveShaderController *m_liveShaders = nullptr;
    RecentFiles *m_recentFiles = nullptr;
    SceneLoadJob *m_loadJob = nullptr;
    std::unique_ptr<SceneShaderFiles> m_sceneShaderFiles;
    QString m_path;
    QString m_lastShaderError;
    // While openAndWait() waits: the failure is its caller's to report.
    bool m_waiting = false;
    QString m_waitedFailure;
};

} // namespace phonglab
