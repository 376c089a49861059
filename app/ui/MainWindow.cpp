#include "MainWindow.h"

#include "render/UniformSnapshot.h"

#include "core/UniformOwner.h"

#include "FileTypes.h"
#include "LiveCheck.h"
#include "LiveShaderController.h"
#include "LoadProgressWidget.h"
#include "MeshStatsText.h"
#include "PerformanceDock.h"
#include "RecentFiles.h"
#include "SceneDock.h"
#include "SceneEditDocks.h"
#include "SceneLoadJob.h"
#include "SceneLoadRequests.h"
#include "ShaderDock.h"
#include "ShaderEditor.h"
#include "ShaderFileSet.h"
#include "ShaderRecovery.h"
#include "UniformsDock.h"
#include "Viewport.h"
#include "core/SceneJson.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>

namespace phonglab {

namespace {

constexpr int kWarningTimeoutMs = 10000;
constexpr int kSceneDockWidth = 340; // fits the stats without eliding most of them

// Scenes embedded in the binary (":/...") can be opened but not written.
bool isWritableLocation(const QString &path)
{
    return !path.isEmpty() && !path.startsWith(QLatin1Char(':'));
}

// Relative mesh paths are relative to the scene file, so saving into another
// folder must rewrite them to keep pointing at the same meshes.
Scene rebasedOnto(Scene scene, const QString &sceneFilePath)
{
    const QDir folder = QFileInfo(sceneFilePath).absoluteDir();
    for (SceneObject &object : scene.objects) {
        const QString resolved = scene.resolveMeshPath(object.mesh);
        if (resolved != object.mesh && isWritableLocation(resolved))
            object.mesh = folder.relativeFilePath(resolved);
    }
    scene.baseDir = folder.absolutePath();
    return scene;
}

QString firstLine(const QString &text)
{
    return text.section(QLatin1Char('\n'), 0, 0);
}

} // namespace

MainWindow::MainWindow(QWidget *parent, const StartupOptions &options)
    : QMainWindow(parent)
    , m_options(options)
    , m_viewport(new Viewport(this))
    , m_loadJob(new SceneLoadJob(m_viewport, this))
    , m_sceneDock(new SceneDock(this))
    , m_shaderDock(new ShaderDock(this))
{
    setCentralWidget(m_viewport);
    addDockWidget(Qt::RightDockWidgetArea, m_sceneDock);
    // Tabbed with the Scene dock so the viewport keeps its width; the code is
    // what a shader playground opens on.
    addDockWidget(Qt::RightDockWidgetArea, m_shaderDock);
    tabifyDockWidget(m_sceneDock, m_shaderDock);
    m_shaderDock->raise();
    resizeDocks({m_sceneDock}, {kSceneDockWidth}, Qt::Horizontal);
    createShaderDock();
    createUniformsDock();
    createPerformanceDock();
    m_editDocks = new SceneEditDocks(this, m_viewport, m_sceneDock);
    m_shaderDock->raise(); // still the tab shown first
    createFileMenu();
    m_editDocks->addEditActions(menuBar()->addMenu(tr("&Edit")));
    // Before the status bar: the verdict comes first among its permanent
    // widgets, where a long diagnosis pushes nothing else out of sight.
    m_liveCheck = new LiveCheck(this, m_viewport, m_liveShaders);
    createViewMenu();
    createStatusBar();
    connectLoading();
    m_liveCheck->pauseWhileLoading(m_loadJob);
    connect(m_uniformsDock, &UniformsDock::valueWritten, m_liveCheck, &LiveCheck::frameChanged);
    connect(m_viewport, &Viewport::frameRendered, this, &MainWindow::showFrameStats);
    connect(m_viewport, &Viewport::glRendererChanged, m_rendererLabel, &QLabel::setText);
    // Queued: the error is raised from inside initializeGL / paintGL, where a
    // dialog must not be opened.
    connect(m_viewport, &Viewport::renderError, this, &MainWindow::showRenderError, Qt::QueuedConnection);
    setScenePath({});
}

// Out of line: LiveShaderController's destructor (a clean exit: the journal
// goes) runs with the dock and the viewport still alive.
MainWindow::~MainWindow()
{
    delete m_liveShaders;
}

void MainWindow::createShaderDock()
{
    m_liveShaders = new LiveShaderController(m_shaderDock, m_viewport, this);
    connect(m_liveShaders, &LiveShaderController::statusMessage, statusBar(), &QStatusBar::showMessage);
    connect(m_viewport, &Viewport::sceneChanged, this,
            [this] { m_liveShaders->followSceneShading(m_viewport->currentScene().shading); });
    // Tests answer through the environment at once; a person is asked once
    // the window is up.
    m_liveShaders->setBuildOnGuiThread(m_options.compileOnGuiThread);
    m_liveShaders->setWarmUp(m_options.warmUp);
    const ShaderRecovery::Answer answer = m_options.recoveryAnswer;
    if (answer != ShaderRecovery::Answer::Ask)
        m_liveShaders->offerRecovery(answer, this);
    else
        QTimer::singleShot(0, this, [this, answer] { m_liveShaders->offerRecovery(answer, this); });
    if (!m_options.typeAfterStart.isEmpty())
        connect(m_viewport, &Viewport::glInitialized, this, &MainWindow::typeTestTextAfterStart,
                Qt::SingleShotConnection);
}

// For the crash-recovery test: an edit made by "the user" in a process the
// test then kills. Typed as an edit, and journaled at once.
void MainWindow::typeTestTextAfterStart()
{
    ShaderEditor *editor = m_shaderDock->editor(ShaderStage::Fragment);
    editor->append(m_options.typeAfterStart);
    m_liveShaders->recovery()->writeNow();
}

// A clean exit forgets the recovery journal: unsaved shaders are offered
// for saving first.
void MainWindow::closeEvent(QCloseEvent *event)
{
    if (m_liveShaders->recovery()->confirmUnsaved(this)) {
        saveWindowSettings();
        event->accept();
    } else {
        event->ignore();
    }
}

namespace {
const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");
constexpr int kWindowStateVersion = 1; // bump when the docks change incompatibly
} // namespace

void MainWindow::saveWindowSettings() const
{
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState(kWindowStateVersion));
}

bool MainWindow::restoreWindowSettings()
{
    const QSettings settings;
    const QByteArray geometry = settings.value(kGeometryKey).toByteArray();
    const QByteArray state = settings.value(kStateKey).toByteArray();
    const bool geometryOk = !geometry.isEmpty() && restoreGeometry(geometry);
    const bool stateOk = !state.isEmpty() && restoreState(state, kWindowStateVersion);
    return geometryOk && stateOk;
}

// Rebuilt from the linked program after every build, including the shipped
// program a scene or a fresh context loads.
void MainWindow::createUniformsDock()
{
    m_uniformsDock = new UniformsDock(this);
    addDockWidget(Qt::RightDockWidgetArea, m_uniformsDock);
    tabifyDockWidget(m_shaderDock, m_uniformsDock);
    m_shaderDock->raise();
    m_uniformsDock->attach(m_viewport, m_shaderDock);
    // Queued: glInitialized comes from inside initializeGL, where the
    // viewport must not be asked to repaint.
    for (auto signal : {&Viewport::glInitialized, &Viewport::sceneChanged})
        connect(m_viewport, signal, m_uniformsDock, &UniformsDock::scheduleRebuild, Qt::QueuedConnection);
    connect(m_viewport, &Viewport::shippedProgramLoaded, m_uniformsDock, &UniformsDock::scheduleRebuild,
            Qt::QueuedConnection);
    connect(m_liveShaders, &LiveShaderController::programApplied, m_uniformsDock, &UniformsDock::scheduleRebuild,
            Qt::QueuedConnection);
}

// Tabbed with the Scene dock: measuring is occasional, the code is not.
void MainWindow::createPerformanceDock()
{
    m_performanceDock = new PerformanceDock(m_viewport, this);
    addDockWidget(Qt::RightDockWidgetArea, m_performanceDock);
    tabifyDockWidget(m_sceneDock, m_performanceDock);
    connect(m_performanceDock, &PerformanceDock::applyModelRequested, this, &MainWindow::applyModel);
}

void MainWindow::applyModel(ShadingMethod method, double detail)
{
    SceneLoadRequest request = modelRequest(m_viewport->currentScene(), method, detail);
    request.shown = [this] { refreshSceneDock(); };
    m_loadJob->start(std::move(request));
}

void MainWindow::createFileMenu()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QAction *open = file->addAction(tr("&Open Scene…"), this, &MainWindow::chooseAndOpenScene);
    open->setShortcut(QKeySequence::Open);
    QAction *openMesh = file->addAction(tr("Open &Mesh…"), this, &MainWindow::chooseAndOpenMeshes);
    openMesh->setShortcut(QKeySequence(tr("Ctrl+Shift+O")));
    m_recentFiles = new RecentFiles(file->addMenu(tr("&Recent")), this);
    connect(m_recentFiles, &RecentFiles::fileChosen, this, [this](const QString &path) { openFilesOrExplain({path}); });
    connect(m_recentFiles, &RecentFiles::missingFileChosen, this, &MainWindow::explainMissingRecentFile);
    file->addSeparator();
    QAction *save = file->addAction(tr("&Save Scene"), this, &MainWindow::saveSceneToCurrentFile);
    save->setShortcut(QKeySequence::Save);
    QAction *saveAs = file->addAction(tr("Save Scene &As…"), this, &MainWindow::chooseAndSaveScene);
    saveAs->setShortcut(QKeySequence(tr("Ctrl+Shift+S")));
    file->addAction(tr("&Export Image…"), this, &MainWindow::chooseAndExportImage);
    file->addSeparator();
    QAction *quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence(tr("Ctrl+Q")));
    quit->setMenuRole(QAction::QuitRole);
}

void MainWindow::createViewMenu()
{
    QMenu *view = menuBar()->addMenu(tr("&View"));
    m_resetCameraAction = view->addAction(tr("&Reset Camera"), m_viewport, &Viewport::resetCamera);
    m_resetCameraAction->setShortcuts({QKeySequence(Qt::Key_R), QKeySequence(Qt::Key_Home)});
    // Bare-key shortcuts only while the viewport has focus, so typing "r" in
    // any other widget (an editor dock) does not move the camera.
    m_resetCameraAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_viewport->addAction(m_resetCameraAction);

    m_lightMarkersAction = view->addAction(tr("Show &Light Markers"));
    m_lightMarkersAction->setCheckable(true);
    m_lightMarkersAction->setChecked(m_viewport->showLightMarkers());
    connect(m_lightMarkersAction, &QAction::toggled, m_viewport, &Viewport::setShowLightMarkers);

    view->addSeparator();
    QAction *dock = m_sceneDock->toggleViewAction();
    dock->setText(tr("&Scene Dock"));
    view->addAction(dock);
    QAction *shaders = m_shaderDock->toggleViewAction();
    shaders->setText(tr("S&haders Dock"));
    view->addAction(shaders);
    QAction *uniforms = m_uniformsDock->toggleViewAction();
    uniforms->setText(tr("&Uniforms Dock"));
    view->addAction(uniforms);
    QAction *performance = m_performanceDock->toggleViewAction();
    performance->setText(tr("&Performance Dock"));
    view->addAction(performance);
    m_editDocks->addDockToggles(view);
    m_liveCheck->addViewActions(view);
}

void MainWindow::createStatusBar()
{
    m_loadProgress = new LoadProgressWidget(m_loadJob, this);
    m_frameLabel = new QLabel(this);
    m_rendererLabel = new QLabel(tr("OpenGL not started"), this);
    statusBar()->addPermanentWidget(m_loadProgress);
    statusBar()->addPermanentWidget(m_frameLabel);
    statusBar()->addPermanentWidget(m_rendererLabel);
}

void MainWindow::connectLoading()
{
    connect(m_viewport, &Viewport::sceneChanged, this, &MainWindow::refreshSceneDock);
    // Queued: the dock is rebuilding itself or its editor is mid-signal when a
    // drop or an edit arrives; both are handled once that is over.
    connect(m_viewport, &Viewport::filesDropped, this, &MainWindow::openFilesOrExplain, Qt::QueuedConnection);
    connect(m_sceneDock, &SceneDock::normalsChangeRequested, this, &MainWindow::changeNormals, Qt::QueuedConnection);
    connect(m_loadJob, &SceneLoadJob::failed, this, &MainWindow::showLoadFailure);
    connect(m_loadJob, &SceneLoadJob::cancelled, this, &MainWindow::showLoadCancelled);
}

Result<> MainWindow::openScene(const QString &path)
{
    m_loadJob->cancel(); // one load at a time
    const SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.ok())
        return fail(loaded.error);
    if (Result<> set = m_viewport->setScene(*loaded.scene); !set)
        return set;
    setScenePath(path);
    openSceneShaders(*loaded.scene);
    if (!loaded.warnings.isEmpty())
        statusBar()->showMessage(loaded.warnings.join(QStringLiteral("; ")), kWarningTimeoutMs);
    else
        statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(path).fileName()), kWarningTimeoutMs);
    return {};
}

Result<> MainWindow::saveScene(const QString &path)
{
    if (Result<> saved = saveShaderBuffers(); !saved)
        return saved;
    Scene scene = rebasedOnto(m_viewport->currentScene(), path);
    addShaderFiles(scene, path);
    scene.uniforms = userUniformValues();
    if (Result<> saved = saveSceneFile(scene, path); !saved)
        return saved;
    setScenePath(path);
    m_recentFiles->add(path);
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), kWarningTimeoutMs);
    return {};
}

namespace {

// Numbers a scene file can hold: scalars, vectors and matrices of float,
// int, uint and bool (not samplers, whose values are texture units).
bool isPlainNumberType(GLenum type)
{
    switch (type) {
    case GL_FLOAT:
    case GL_FLOAT_VEC2:
    case GL_FLOAT_VEC3:
    case GL_FLOAT_VEC4:
    case GL_INT:
    case GL_INT_VEC2:
    case GL_INT_VEC3:
    case GL_INT_VEC4:
    case GL_UNSIGNED_INT:
    case GL_UNSIGNED_INT_VEC2:
    case GL_UNSIGNED_INT_VEC3:
    case GL_UNSIGNED_INT_VEC4:
    case GL_BOOL:
    case GL_BOOL_VEC2:
    case GL_BOOL_VEC3:
    case GL_BOOL_VEC4:
    case GL_FLOAT_MAT2:
    case GL_FLOAT_MAT3:
    case GL_FLOAT_MAT4: return true;
    default: return false;
    }
}

} // namespace

// The running program's values for the uniforms only the user sets (the
// Uniforms dock's editable rows), so a saved scene reopens with them.
std::map<QString, std::vector<double>> MainWindow::userUniformValues()
{
    std::map<QString, std::vector<double>> values;
    const UniformSnapshot snapshot = m_viewport->programSnapshot();
    for (const UniformValue &v : snapshot.values) {
        const QString name = QString::fromUtf8(v.name);
        if (!isPlainNumberType(v.type) || uniformOwner(name.section(QLatin1Char('['), 0, 0)) != UniformOwner::User)
            continue;
        std::vector<double> numbers;
        for (int i = 0; i < v.components; ++i)
            numbers.push_back(v.kind == UniformValue::Kind::Float     ? double(v.floats[i])
                                  : v.kind == UniformValue::Kind::Int ? double(v.ints[i])
                                                                      : double(v.uints[i]));
        values[name] = std::move(numbers);
    }
    return values;
}

// A scene names its shader files, so their unsaved edits are saved with it
// (a shipped shader's go to its user copy).
Result<> MainWindow::saveShaderBuffers()
{
    for (const ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
        if (!m_shaderDock->isDirty(stage))
            continue;
        if (const Result<> saved = m_shaderDock->save(stage); !saved)
            return fail(tr("Cannot save the %1 shader: %2").arg(stageName(stage), saved.error()));
    }
    return {};
}

// The dock's files, where they are not shipped ones: relative to the scene
// file when under its folder, else absolute.
void MainWindow::addShaderFiles(Scene &scene, const QString &sceneFilePath) const
{
    const QDir folder = QFileInfo(sceneFilePath).absoluteDir();
    const auto entry = [&](ShaderStage stage) {
        const QString file = m_shaderDock->filePath(stage);
        if (file.isEmpty() || !isWritableLocation(file) || m_shaderDock->files()->isShipped(file))
            return QString();
        const QString absolute = QFileInfo(file).absoluteFilePath();
        const QString relative = folder.relativeFilePath(absolute);
        return relative.startsWith(QLatin1String("..")) || QDir::isAbsolutePath(relative) ? absolute : relative;
    };
    scene.vertexShader = entry(ShaderStage::Vertex);
    scene.fragmentShader = entry(ShaderStage::Fragment);
}

void MainWindow::openSceneShaders(const Scene &scene)
{
    m_lastShaderError.clear();
    if (scene.vertexShader.isEmpty() && scene.fragmentShader.isEmpty())
        return;
    if (m_shaderDock->hasUnsavedChanges()) {
        // Unsaved edits are never replaced behind the user's back.
        statusBar()->showMessage(tr("Kept your unsaved shader edits; the scene's shader files were not loaded"),
                                 kWarningTimeoutMs);
        return;
    }
    const std::pair<ShaderStage, QString> files[] = {{ShaderStage::Vertex, scene.vertexShader},
                                                     {ShaderStage::Fragment, scene.fragmentShader}};
    QStringList missing;
    for (const auto &[stage, name] : files) {
        const QString path = scene.resolveShaderPath(name);
        if (!name.isEmpty() && !QFileInfo(path).isFile())
            missing << tr("shaders.%1: %2: file not found")
                           .arg(stage == ShaderStage::Vertex ? QStringLiteral("vertex") : QStringLiteral("fragment"),
                                QDir::toNativeSeparators(path));
    }
    // The shading method's shipped shaders, shown and built, under whatever is missing.
    if (!missing.isEmpty())
        m_liveShaders->applyPreset(scene.shading);
    bool opened = false;
    for (const auto &[stage, name] : files) {
        const QString path = scene.resolveShaderPath(name);
        if (name.isEmpty() || !QFileInfo(path).isFile())
            continue;
        // One at a time, on its stage's tab, so any suffix goes to the right stage.
        m_shaderDock->tabs()->setCurrentWidget(m_shaderDock->editor(stage));
        if (const Result<> read = m_shaderDock->openFiles({path}))
            opened = true;
        else
            missing << tr("shaders.%1: %2").arg(stageName(stage), read.error());
    }
    if (opened)
        m_liveShaders->buildNow(); // a failure shows in the dock; the last good program stays
    if (!missing.isEmpty()) {
        m_lastShaderError = missing.join(QLatin1Char('\n'));
        statusBar()->showMessage(tr("Cannot open the scene's shaders: %1").arg(missing.join(QStringLiteral("; "))),
                                 kWarningTimeoutMs);
        warn(tr("Cannot open the scene's shaders"),
             tr("%1\n\nThe scene uses its shading method's shipped shaders instead.").arg(m_lastShaderError));
    }
}

Result<> MainWindow::openFiles(const QStringList &paths)
{
    if (const QString reason = whyNotOpenable(paths); !reason.isEmpty())
        return fail(reason);
    if (isSceneFile(paths.front())) // then it is the only one
        return startSceneLoad(paths.front());
    m_lastFolder = QFileInfo(paths.front()).absolutePath();
    SceneLoadRequest request = meshFilesRequest(m_viewport->currentScene(), paths);
    request.shown = [this, paths] {
        setScenePath({}, fileNameList(paths)); // a new, unsaved scene
        for (const QString &path : paths)
            m_recentFiles->add(path);
        statusBar()->showMessage(tr("Opened %1").arg(fileNameList(paths)), kWarningTimeoutMs);
    };
    m_loadJob->start(std::move(request));
    return {};
}

// The scene file itself is small and parsed here, so a broken one is refused
// at once; only its meshes load in the background.
Result<> MainWindow::startSceneLoad(const QString &path)
{
    const SceneLoadResult parsed = loadSceneFile(path);
    if (!parsed.ok())
        return fail(parsed.error);
    SceneLoadRequest request = sceneFileRequest(path, *parsed.scene);
    request.shown = [this, path, warnings = parsed.warnings, scene = *parsed.scene] {
        setScenePath(path);
        openSceneShaders(scene);
        m_recentFiles->add(path);
        const QString message =
            warnings.isEmpty() ? tr("Opened %1").arg(QFileInfo(path).fileName()) : warnings.join(QStringLiteral("; "));
        statusBar()->showMessage(message, kWarningTimeoutMs);
    };
    m_loadJob->start(std::move(request));
    return {};
}

void MainWindow::changeNormals(int objectIndex, const NormalOptions &options)
{
    const Scene current = m_viewport->currentScene();
    if (objectIndex < 0 || objectIndex >= int(current.objects.size()))
        return;
    SceneLoadRequest request = normalsRequest(current, objectIndex, options);
    request.shown = [this, objectIndex] {
        const Scene scene = m_viewport->currentScene();
        const SceneObject &object = scene.objects[objectIndex];
        const MeshStats stats = m_viewport->meshInfo().value(meshKey(scene, object)).stats;
        statusBar()->showMessage(
            tr("Normals of %1: %2").arg(QFileInfo(object.mesh).fileName(), normalsDescription(stats, false)),
            kWarningTimeoutMs);
    };
    m_loadJob->start(std::move(request));
}

void MainWindow::chooseAndOpenScene()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Scene"), dialogFolder(), sceneFileFilter());
    if (!path.isEmpty())
        openFilesOrExplain({path});
}

void MainWindow::chooseAndOpenMeshes()
{
    const QStringList paths = QFileDialog::getOpenFileNames(this, tr("Open Mesh"), dialogFolder(), meshFileFilter());
    if (!paths.isEmpty())
        openFilesOrExplain(paths);
}

void MainWindow::openFilesOrExplain(const QStringList &paths)
{
    const Result<> opened = openFiles(paths);
    if (opened)
        return;
    statusBar()->showMessage(tr("Cannot open: %1").arg(firstLine(opened.error())), kWarningTimeoutMs);
    warn(tr("Cannot open"), tr("%1\n\nThe current scene is still open.").arg(opened.error()));
}

void MainWindow::explainMissingRecentFile(const QString &path)
{
    warn(tr("File not found"),
         tr("%1\n\nThe file no longer exists; it was removed from the recent files.")
             .arg(QDir::toNativeSeparators(path)));
}

void MainWindow::saveSceneToCurrentFile()
{
    if (!isWritableLocation(m_scenePath)) {
        chooseAndSaveScene();
        return;
    }
    if (const Result<> saved = saveScene(m_scenePath); !saved)
        warn(tr("Cannot save scene"), tr("%1\n\n%2").arg(QDir::toNativeSeparators(m_scenePath), saved.error()));
}

void MainWindow::chooseAndSaveScene()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Save Scene As"), dialogFolder(), sceneFileFilter());
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    // saveSceneFile writes atomically: on failure the old file and the scene
    // in the window are both untouched, so the user can retry elsewhere.
    if (const Result<> saved = saveScene(path); !saved)
        warn(tr("Cannot save scene"), tr("%1\n\n%2").arg(QDir::toNativeSeparators(path), saved.error()));
}

void MainWindow::showFrameStats(double milliseconds, qint64 triangles)
{
    const std::optional<QString> depth = depthPrecisionWarning(m_viewport->depthRange());
    m_frameLabel->setText(tr("%1 ms · %2 triangles%3")
                              .arg(milliseconds, 0, 'f', 2)
                              .arg(QLocale().toString(triangles))
                              .arg(depth ? tr(" · low depth precision") : QString()));
    m_frameLabel->setToolTip(depth.value_or(QString()));
    // Said once when it starts, not on every frame of an orbit.
    if (depth && !m_depthWarningShown)
        statusBar()->showMessage(*depth, 15000);
    m_depthWarningShown = depth.has_value();
}

void MainWindow::showRenderError(const QString &message)
{
    statusBar()->showMessage(tr("Rendering failed: %1").arg(firstLine(message)));
    auto *box = new QMessageBox(QMessageBox::Critical, tr("Rendering failed"), message, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::showLoadFailure(const QString &label, const QString &error)
{
    statusBar()->showMessage(tr("Cannot load %1: %2").arg(label, firstLine(error)), kWarningTimeoutMs);
    warn(tr("Cannot load %1").arg(label),
         tr("Cannot load %1:\n\n%2\n\nThe current scene is still shown.").arg(label, error));
    refreshSceneDock(); // its normals control goes back to what is shown
}

void MainWindow::showLoadCancelled(const QString &label)
{
    statusBar()->showMessage(tr("Loading %1 cancelled").arg(label), kWarningTimeoutMs);
    // A load superseded by a newer one leaves the dock showing the newer request.
    if (!m_loadJob->isRunning())
        refreshSceneDock();
}

void MainWindow::refreshSceneDock()
{
    m_sceneDock->showScene(m_viewport->currentScene(), m_viewport->meshInfo());
}

void MainWindow::setScenePath(const QString &path, const QString &title)
{
    m_scenePath = path;
    if (isWritableLocation(path))
        m_lastFolder = QFileInfo(path).absolutePath();
    QString name = title;
    if (name.isEmpty())
        name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    setWindowTitle(tr("%1 — PhongLab").arg(name));
}

QString MainWindow::dialogFolder() const
{
    return m_lastFolder.isEmpty() ? QDir::homePath() : m_lastFolder;
}

// Non-blocking, so neither a load finishing nor a drop ever waits on a
// dialog, and nothing stalls the event loop.
Result<> MainWindow::exportImage(const QString &path, const QSize &size)
{
    const QImage image = m_viewport->renderImage(size);
    if (image.isNull())
        return fail(tr("Cannot render a %1×%2 image").arg(size.width()).arg(size.height()));
    if (!image.save(path, "PNG"))
        return fail(tr("Cannot write %1").arg(path));
    return {};
}

void MainWindow::chooseAndExportImage()
{
    const QSize shown = m_viewport->size() * m_viewport->devicePixelRatioF();
    bool ok = false;
    const int width =
        QInputDialog::getInt(this, tr("Export Image"), tr("Width (pixels):"), shown.width(), 1, 16384, 1, &ok);
    if (!ok)
        return;
    const int height =
        QInputDialog::getInt(this, tr("Export Image"), tr("Height (pixels):"), shown.height(), 1, 16384, 1, &ok);
    if (!ok)
        return;
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export Image"), dialogFolder(), tr("PNG images (*.png)"));
    if (path.isEmpty())
        return;
    if (const Result<> exported = exportImage(path, {width, height}); !exported)
        warn(tr("Export Image"), exported.error());
    else
        statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()), kWarningTimeoutMs);
}

void MainWindow::warn(const QString &title, const QString &message)
{
    auto *box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

} // namespace phonglab
