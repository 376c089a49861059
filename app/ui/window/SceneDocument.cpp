#include "SceneDocument.h"

#include "RecentFiles.h"
#include "WarningBox.h"
#include "core/project/ProjectShader.h"
#include "core/scene/SceneJson.h"
#include "core/scene/ScenePaths.h"
#include "render/program/SceneUniforms.h"
#include "ui/scene/FileTypes.h"
#include "ui/scene/MeshStatsText.h"
#include "ui/scene/SceneLoadJob.h"
#include "ui/scene/SceneLoadRequests.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/shaders/SceneShaderFiles.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/viewport/Viewport.h"

#include <QDir>
#include <QFileInfo>
#include <QMainWindow>
#include <QStatusBar>
#include <QTimer>

#include <utility>

namespace phonglab {

namespace {

constexpr int kMessageTimeoutMs = 10000;

} // namespace

SceneDocument::SceneDocument(QMainWindow *window, Viewport *viewport, ShaderDock *shaders,
                             LiveShaderController *liveShaders, RecentFiles *recentFiles)
    : QObject(window)
    , m_window(window)
    , m_viewport(viewport)
    , m_shaders(shaders)
    , m_liveShaders(liveShaders)
    , m_recentFiles(recentFiles)
    , m_loadJob(new SceneLoadJob(viewport, this))
    , m_sceneShaderFiles(std::make_unique<SceneShaderFiles>(shaders, liveShaders))
{
    connect(m_loadJob, &SceneLoadJob::failed, this, &SceneDocument::showLoadFailure);
    connect(m_loadJob, &SceneLoadJob::cancelled, this, &SceneDocument::showLoadCancelled);
    setPath({});
}

SceneDocument::~SceneDocument() = default;

Result<> SceneDocument::open(const QString &path, const QString &vertexPath,
                             const QString &fragmentPath)
{
    return startLoading(path, vertexPath, fragmentPath, Remember::InRecentFiles);
}

Result<> SceneDocument::openAndWait(const QString &path)
{
    if (Result<> started = startLoading(path, {}, {}, Remember::Nothing); !started)
        return started;
    m_waiting = true;
    m_waitedFailure.clear();
    m_loadJob->finishNow();
    m_waiting = false;
    if (!m_waitedFailure.isEmpty())
        return fail(std::exchange(m_waitedFailure, {}));
    return {};
}

// The scene file itself is small and parsed here, so a broken one is refused
// at once; only its meshes load in the background. Shader files given here
// take the place of the scene's own.
Result<> SceneDocument::startLoading(const QString &path, const QString &vertexPath,
                                     const QString &fragmentPath, Remember remember)
{
    SceneLoadResult parsed = loadSceneFile(path);
    if (!parsed.ok())
        return fail(QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(path), parsed.error));
    // A locator (index.html#vsSource) is absolute already where a project gave it.
    const auto absolute = [](const QString &file) {
        return isShaderLocator(file) ? file : QFileInfo(file).absoluteFilePath();
    };
    if (!vertexPath.isEmpty())
        parsed.scene->vertexShader = absolute(vertexPath);
    if (!fragmentPath.isEmpty())
        parsed.scene->fragmentShader = absolute(fragmentPath);
    SceneLoadRequest request = sceneFileRequest(path, *parsed.scene);
    request.shown = [this, path, remember, warnings = parsed.warnings, scene = *parsed.scene] {
        setPath(path);
        openSceneShaders(scene);
        if (remember == Remember::InRecentFiles)
            m_recentFiles->add(path);
        showStatus(warnings.isEmpty() ? tr("Opened %1").arg(QFileInfo(path).fileName())
                                      : warnings.join(QStringLiteral("; ")));
    };
    m_loadJob->start(std::move(request));
    return {};
}

Result<> SceneDocument::openFiles(const QStringList &paths)
{
    if (const QString reason = whyNotOpenable(paths); !reason.isEmpty())
        return fail(reason);
    if (isSceneFile(paths.front())) // then it is the only one
        return open(paths.front());
    emit folderUsed(paths.front());
    SceneLoadRequest request = meshFilesRequest(m_viewport->currentScene(), paths);
    request.shown = [this, paths] {
        setPath({}, fileNameList(paths)); // a new, unsaved scene
        for (const QString &path : paths)
            m_recentFiles->add(path);
        showStatus(tr("Opened %1").arg(fileNameList(paths)));
    };
    m_loadJob->start(std::move(request));
    return {};
}

Result<> SceneDocument::openSubmission(const QString &scenePath, const QString &vertexPath,
                                       const QString &fragmentPath)
{
    if (!isSceneFile(scenePath))
        return fail(tr("%1: not a scene file (.json)").arg(scenePath));
    for (const QString &file : {vertexPath, fragmentPath})
        if (!file.isEmpty() && !QFileInfo(file).isFile() && !isShaderLocator(file))
            return fail(tr("%1: no such shader file").arg(file));
    return open(scenePath, vertexPath, fragmentPath);
}

Result<> SceneDocument::openShaders(const QString &vertexPath, const QString &fragmentPath)
{
    return openShaderFiles({vertexPath, fragmentPath});
}

Result<> SceneDocument::openShaderFiles(const QStringList &paths)
{
    if (const Result<> opened = m_shaders->openFiles(paths); !opened)
        return opened;
    // The bindings chosen in the Uniforms dock were for the shaders these
    // replace: another project's names mean what that project meant.
    if (!m_viewport->currentScene().bindings.empty())
        m_viewport->program().setBindings({});
    m_liveShaders->buildNow();
    return {};
}

void SceneDocument::openSceneShaders(const Scene &scene)
{
    const SceneShaderFiles::Opened opened = m_sceneShaderFiles->open(scene);
    m_lastShaderError = opened.unusable.join(QLatin1Char('\n'));
    if (!opened.note.isEmpty())
        showStatus(opened.note);
    if (opened.unusable.isEmpty())
        return;
    showStatus(
        tr("Cannot open the scene's shaders: %1").arg(opened.unusable.join(QStringLiteral("; "))));
    openWarning(m_window, tr("Cannot open the scene's shaders"),
                tr("%1\n\nThe scene uses its shading method's shipped shaders instead.")
                    .arg(m_lastShaderError));
}

Result<> SceneDocument::save(const QString &path)
{
    if (Result<> saved = m_sceneShaderFiles->saveEdits(); !saved)
        return saved;
    Scene current = m_viewport->currentScene();
    current.camera = m_viewport->cameraToSave();
    Scene scene = rebasedOnto(current, path);
    m_sceneShaderFiles->nameIn(scene, path);
    ViewProgram &program = m_viewport->program();
    scene.uniforms = userUniformValues(program.values(), program.bindings());
    if (Result<> saved = saveSceneFile(scene, path); !saved)
        return saved;
    setPath(path);
    m_recentFiles->add(path);
    showStatus(tr("Saved %1").arg(QFileInfo(path).fileName()));
    return {};
}

Result<> SceneDocument::exportImage(const QString &path, const QSize &size)
{
    const QImage image = m_viewport->renderImage(size);
    if (image.isNull())
        return fail(tr("Cannot render a %1×%2 image").arg(size.width()).arg(size.height()));
    if (!image.save(path, "PNG"))
        return fail(tr("Cannot write %1").arg(path));
    return {};
}

void SceneDocument::changeNormals(int objectIndex, const NormalOptions &options)
{
    const Scene current = m_viewport->currentScene();
    if (objectIndex < 0 || objectIndex >= int(current.objects.size()))
        return;
    SceneLoadRequest request = normalsRequest(current, objectIndex, options);
    request.shown = [this, objectIndex] {
        const Scene scene = m_viewport->currentScene();
        const SceneObject &object = scene.objects[objectIndex];
        const MeshStats stats = m_viewport->meshInfo().value(meshKey(scene, object)).stats;
        showStatus(tr("Normals of %1: %2")
                       .arg(QFileInfo(object.mesh).fileName(), normalsDescription(stats, false)));
    };
    m_loadJob->start(std::move(request));
}

void SceneDocument::applyFit(ShadingMethod method, double detail)
{
    m_loadJob->start(fitRequest(m_viewport->currentScene(), method, detail));
}

void SceneDocument::setAutoDetail(bool on)
{
    m_loadJob->start(autoDetailRequest(m_viewport->currentScene(), on));
}

void SceneDocument::offerRecovery(ShaderRecovery::Answer answer, const QString &testText)
{
    // Tests answer through the environment at once; a person is asked once
    // the window is up.
    if (answer != ShaderRecovery::Answer::Ask)
        askAboutRecovery(answer);
    else
        QTimer::singleShot(0, this, [this, answer] { askAboutRecovery(answer); });
    if (!testText.isEmpty())
        connect(
            m_viewport, &Viewport::glInitialized, this,
            [this, testText] { typeAfterStart(testText); }, Qt::SingleShotConnection);
}

// Restored text builds at once, unless it was on its way to the driver when
// that session died: then it waits for F5.
void SceneDocument::askAboutRecovery(ShaderRecovery::Answer answer)
{
    const ShaderRecovery::Outcome outcome = m_liveShaders->recovery()->offer(answer, m_window);
    if (outcome.note.isEmpty())
        return;
    if (outcome.restored)
        m_liveShaders->takeRestoredText(shadingFromName(outcome.shading),
                                        outcome.suspect
                                            ? LiveShaderController::AutoBuild::OnlyOnF5
                                            : LiveShaderController::AutoBuild::AfterPause);
    m_shaders->setCompileStatus(outcome.note, !outcome.suspect);
    m_window->statusBar()->showMessage(outcome.note);
}

// For the crash-recovery test: an edit made by "the user" in a process the
// test then kills. Typed as an edit, and journaled at once.
void SceneDocument::typeAfterStart(const QString &text)
{
    m_shaders->editor(ShaderStage::Fragment)->append(text);
    m_liveShaders->recovery()->writeNow();
}

bool SceneDocument::confirmClose()
{
    return m_liveShaders->recovery()->confirmUnsaved(m_window);
}

void SceneDocument::showLoadFailure(const QString &label, const QString &error)
{
    if (m_waiting) {
        m_waitedFailure = error;
        return;
    }
    showStatus(tr("Cannot load %1: %2").arg(label, firstLine(error)));
    openWarning(m_window, tr("Cannot load %1").arg(label),
                tr("Cannot load %1:\n\n%2\n\nThe current scene is still shown.").arg(label, error));
}

void SceneDocument::showLoadCancelled(const QString &label)
{
    showStatus(tr("Loading %1 cancelled").arg(label));
}

void SceneDocument::setPath(const QString &path, const QString &title)
{
    m_path = path;
    emit folderUsed(path);
    QString name = title;
    if (name.isEmpty())
        name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    m_window->setWindowTitle(tr("%1 — PhongLab").arg(name));
}

void SceneDocument::showStatus(const QString &message)
{
    m_window->statusBar()->showMessage(message, kMessageTimeoutMs);
}

} // namespace phonglab
