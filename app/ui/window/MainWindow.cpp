#include "MainWindow.h"

#include "core/support/Language.h"
#include "core/project/ProjectShader.h"

#include "DefaultLayout.h"
#include "FileMenu.h"
#include "FileTypes.h"
#include "LanguageMenu.h"
#include "LoadProgressWidget.h"
#include "RecentFiles.h"
#include "WarningBox.h"
#include "core/scene/SceneJson.h"
#include "core/scene/ScenePaths.h"
#include "render/SceneUniforms.h"
#include "ui/check/LiveCheck.h"
#include "ui/check/PixelInspectorDock.h"
#include "ui/help/HelpMenu.h"
#include "ui/performance/PerformanceDock.h"
#include "ui/scene/LightsDock.h"
#include "ui/scene/MaterialDock.h"
#include "ui/scene/MeshStatsText.h"
#include "ui/scene/ObjectDock.h"
#include "ui/scene/SceneDock.h"
#include "ui/scene/SceneEditDockSet.h"
#include "ui/scene/SceneLoadJob.h"
#include "ui/scene/SceneLoadRequests.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/shaders/SceneShaderFiles.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/shaders/ShaderFileSet.h"
#include "ui/shaders/ShaderRecovery.h"
#include "ui/uniforms/UniformsDock.h"
#include "ui/viewport/DetailLevelLabel.h"
#include "ui/viewport/FrameStatsLabel.h"
#include "ui/viewport/Viewport.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>

#include <algorithm>
#include <utility>

namespace phonglab {

namespace {

constexpr int kWarningTimeoutMs = 10000;
} // namespace

MainWindow::MainWindow(QWidget *parent, const StartupOptions &options)
    : QMainWindow(parent)
    , m_options(options)
    , m_viewport(new Viewport(this, !options.presentOnGuiThread))
    , m_loadJob(new SceneLoadJob(m_viewport, this))
    , m_sceneDock(new SceneDock(this))
    , m_shaderDock(new ShaderDock(this))
{
    setCentralWidget(m_viewport);
    addDockWidget(Qt::LeftDockWidgetArea, m_sceneDock);
    addDockWidget(Qt::RightDockWidgetArea, m_shaderDock);
    createShaderDock();
    createUniformsDock();
    createPerformanceDock();
    m_editDocks = new SceneEditDockSet(this, m_viewport);
    createFileMenu();
    m_editDocks->addEditActions(menuBar()->addMenu(tr("&Edit")));
    // Before the status bar: the verdict comes first among its permanent
    // widgets, where a long diagnosis pushes nothing else out of sight.
    m_liveCheck = new LiveCheck(this, m_viewport, m_liveShaders);
    createViewMenu();
    new HelpMenu(this, menuBar()->addMenu(tr("&Help"))); // last: after every other menu
    createStatusBar();
    connectLoading();
    m_liveCheck->pauseWhileLoading(m_loadJob);
    connect(m_uniformsDock, &UniformsDock::valueWritten, m_liveCheck, &LiveCheck::frameChanged);
    connect(m_viewport, &Viewport::glRendererChanged, m_rendererLabel, &QLabel::setText);
    connect(m_viewport, &Viewport::framesHeldAfter, this, [this](double ms) {
        statusBar()->showMessage(
            tr("One frame took %1 ms: the view draws again when you click, scroll or press a key "
               "in it")
                .arg(sentenceNumber(ms, 'f', 0)));
    });
    // Queued: the error is raised from inside the view's GL start or a frame, where a
    // dialog must not be opened.
    connect(m_viewport, &Viewport::renderError, this, &MainWindow::showRenderError,
            Qt::QueuedConnection);
    setScenePath({});
    for (QDockWidget *dock : std::initializer_list<QDockWidget *>{
             m_sceneDock, m_editDocks->objectDock(), m_editDocks->lightsDock(),
             m_editDocks->materialDock()})
        scrollWhenShort(dock);
    setGeometry(defaultWindowGeometry(screen()->availableGeometry()));
    resetLayout();
}

WindowDocks MainWindow::docks() const
{
    return {m_sceneDock,
            m_editDocks->objectDock(),
            m_editDocks->lightsDock(),
            m_shaderDock,
            m_editDocks->materialDock(),
            m_uniformsDock,
            m_liveCheck->inspector(),
            m_performanceDock};
}

void MainWindow::resetLayout()
{
    m_shaderDock->ensurePolished();
    applyDefaultLayout(*this, docks(), m_shaderDock->sizeHint().width());
}

// The default layout is laid out again for the size the window is shown
// at (a test's, or the one restored without its docks' state).
void MainWindow::showEvent(QShowEvent *event)
{
    if (std::exchange(m_defaultLayoutDue, false))
        resetLayout();
    QMainWindow::showEvent(event);
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
    m_sceneShaderFiles = std::make_unique<SceneShaderFiles>(m_shaderDock, m_liveShaders);
    connect(m_liveShaders, &LiveShaderController::statusMessage, statusBar(),
            &QStatusBar::showMessage);
    connect(m_viewport, &Viewport::sceneChanged, this,
            [this] { m_liveShaders->followSceneShading(m_viewport->currentScene().shading); });
    // Tests answer through the environment at once; a person is asked once
    // the window is up.
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
// Bump when the default layout changes: a layout saved under another
// version gives way to the new default once (2: the code beside the view;
// 3: the code with most of the column's height).
constexpr int kWindowStateVersion = 3;
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
    m_defaultLayoutDue = !stateOk;
    if (!stateOk)
        resetLayout(); // for the restored size
    return geometryOk && stateOk;
}

// Rebuilt from the linked program after every build, including the shipped
// program a scene or a fresh context loads.
void MainWindow::createUniformsDock()
{
    m_uniformsDock = new UniformsDock(this);
    addDockWidget(Qt::RightDockWidgetArea, m_uniformsDock);
    m_uniformsDock->attach(m_viewport, m_shaderDock);
    // Queued: glInitialized comes from inside the view's GL start, where the
    // viewport must not be asked to repaint.
    for (auto signal : {&Viewport::glInitialized, &Viewport::sceneChanged})
        connect(m_viewport, signal, m_uniformsDock, &UniformsDock::scheduleRebuild,
                Qt::QueuedConnection);
    connect(m_viewport, &Viewport::shippedProgramLoaded, m_uniformsDock,
            &UniformsDock::scheduleRebuild, Qt::QueuedConnection);
    // Direct: the new program's first frame may be presented already and
    // be booked at the next turn of the event loop; the rows follow it.
    connect(m_liveShaders, &LiveShaderController::programApplied, m_uniformsDock,
            &UniformsDock::scheduleRebuild);
}

// Hidden until asked for (DefaultLayout): measuring is occasional.
void MainWindow::createPerformanceDock()
{
    m_performanceDock = new PerformanceDock(m_viewport, m_options.benchExecutable, this);
    addDockWidget(Qt::LeftDockWidgetArea, m_performanceDock);
    connect(m_performanceDock, &PerformanceDock::applyModelRequested, this,
            &MainWindow::applyModel);
    connect(m_performanceDock, &PerformanceDock::autoDetailRequested, this, [this](bool on) {
        SceneLoadRequest request = autoDetailRequest(m_viewport->currentScene(), on);
        request.shown = [this] { refreshSceneDock(); };
        m_loadJob->start(std::move(request));
    });
    new DetailLevelLabel(m_viewport);
}

void MainWindow::applyModel(ShadingMethod method, double detail)
{
    SceneLoadRequest request = modelRequest(m_viewport->currentScene(), method, detail);
    request.shown = [this] { refreshSceneDock(); };
    m_loadJob->start(std::move(request));
}

void MainWindow::createFileMenu()
{
    m_fileMenu = new FileMenu(this, menuBar()->addMenu(tr("&File")));
    m_recentFiles = m_fileMenu->recentFiles();
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

    QAction *resetLayout = view->addAction(tr("Reset &Layout"), this, &MainWindow::resetLayout);
    resetLayout->setObjectName(QStringLiteral("resetLayout"));
    resetLayout->setToolTip(tr("Put every dock back where a new window has it"));

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

    view->addSeparator();
    auto *language = new LanguageMenu(view->addMenu(tr("L&anguage")), this);
    connect(language, &LanguageMenu::chosen, this,
            [this](const QString &message) { statusBar()->showMessage(message, 8000); });
}

void MainWindow::createStatusBar()
{
    m_loadProgress = new LoadProgressWidget(m_loadJob, this);
    m_rendererLabel = new QLabel(tr("OpenGL not started"), this);
    statusBar()->addPermanentWidget(m_loadProgress);
    statusBar()->addPermanentWidget(new FrameStatsLabel(m_viewport, statusBar()));
    statusBar()->addPermanentWidget(m_rendererLabel);
}

void MainWindow::connectLoading()
{
    connect(m_viewport, &Viewport::sceneChanged, this, &MainWindow::refreshSceneDock);
    // Queued: the dock is rebuilding itself or its editor is mid-signal when a
    // drop or an edit arrives; both are handled once that is over.
    connect(m_viewport, &Viewport::filesDropped, m_fileMenu, &FileMenu::openOrExplain,
            Qt::QueuedConnection);
    connect(m_sceneDock, &SceneDock::normalsChangeRequested, this, &MainWindow::changeNormals,
            Qt::QueuedConnection);
    connect(m_loadJob, &SceneLoadJob::failed, this, &MainWindow::showLoadFailure);
    connect(m_loadJob, &SceneLoadJob::cancelled, this, &MainWindow::showLoadCancelled);
}

Result<> MainWindow::openScene(const QString &path)
{
    m_loadJob->cancel(); // one load at a time
    const SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.ok())
        return fail(QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(path), loaded.error));
    if (Result<> set = m_viewport->setScene(*loaded.scene); !set)
        return set;
    setScenePath(path);
    openSceneShaders(*loaded.scene);
    if (!loaded.warnings.isEmpty())
        statusBar()->showMessage(loaded.warnings.join(QStringLiteral("; ")), kWarningTimeoutMs);
    else
        statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(path).fileName()),
                                 kWarningTimeoutMs);
    return {};
}

Result<> MainWindow::saveScene(const QString &path)
{
    if (Result<> saved = m_sceneShaderFiles->saveEdits(); !saved)
        return saved;
    Scene current = m_viewport->currentScene();
    current.camera = m_viewport->cameraToSave();
    Scene scene = rebasedOnto(current, path);
    m_sceneShaderFiles->nameIn(scene, path);
    scene.uniforms =
        userUniformValues(m_viewport->programSnapshot(), m_viewport->programBindings());
    if (Result<> saved = saveSceneFile(scene, path); !saved)
        return saved;
    setScenePath(path);
    m_recentFiles->add(path);
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), kWarningTimeoutMs);
    return {};
}

void MainWindow::openSceneShaders(const Scene &scene)
{
    const SceneShaderFiles::Opened opened = m_sceneShaderFiles->open(scene);
    m_lastShaderError = opened.unusable.join(QLatin1Char('\n'));
    if (!opened.note.isEmpty())
        statusBar()->showMessage(opened.note, kWarningTimeoutMs);
    if (opened.unusable.isEmpty())
        return;
    statusBar()->showMessage(
        tr("Cannot open the scene's shaders: %1").arg(opened.unusable.join(QStringLiteral("; "))),
        kWarningTimeoutMs);
    warn(tr("Cannot open the scene's shaders"),
         tr("%1\n\nThe scene uses its shading method's shipped shaders instead.")
             .arg(m_lastShaderError));
}

Result<> MainWindow::openFiles(const QStringList &paths)
{
    if (const QString reason = whyNotOpenable(paths); !reason.isEmpty())
        return fail(reason);
    if (isSceneFile(paths.front())) // then it is the only one
        return startSceneLoad(paths.front());
    m_fileMenu->rememberFolderOf(paths.front());
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

Result<> MainWindow::openSubmission(const QString &scenePath, const QString &vertexPath,
                                    const QString &fragmentPath)
{
    if (!isSceneFile(scenePath))
        return fail(tr("%1: not a scene file (.json)").arg(scenePath));
    for (const QString &file : {vertexPath, fragmentPath})
        if (!file.isEmpty() && !QFileInfo(file).isFile() && !isShaderLocator(file))
            return fail(tr("%1: no such shader file").arg(file));
    return startSceneLoad(scenePath, vertexPath, fragmentPath);
}

Result<> MainWindow::openShaders(const QString &vertexPath, const QString &fragmentPath)
{
    if (const Result<> opened = m_shaderDock->openFiles({vertexPath, fragmentPath}); !opened)
        return opened;
    m_liveShaders->buildNow();
    return {};
}

// The scene file itself is small and parsed here, so a broken one is refused
// at once; only its meshes load in the background. Shader files given here
// take the place of the scene's own.
Result<> MainWindow::startSceneLoad(const QString &path, const QString &vertexPath,
                                    const QString &fragmentPath)
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
    request.shown = [this, path, warnings = parsed.warnings, scene = *parsed.scene] {
        setScenePath(path);
        openSceneShaders(scene);
        m_recentFiles->add(path);
        const QString message = warnings.isEmpty() ? tr("Opened %1").arg(QFileInfo(path).fileName())
                                                   : warnings.join(QStringLiteral("; "));
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
            tr("Normals of %1: %2")
                .arg(QFileInfo(object.mesh).fileName(), normalsDescription(stats, false)),
            kWarningTimeoutMs);
    };
    m_loadJob->start(std::move(request));
}

void MainWindow::showRenderError(const QString &message)
{
    statusBar()->showMessage(tr("Rendering failed: %1").arg(firstLine(message)));
    openWarning(this, tr("Rendering failed"), message, QMessageBox::Critical);
}

void MainWindow::showLoadFailure(const QString &label, const QString &error)
{
    statusBar()->showMessage(tr("Cannot load %1: %2").arg(label, firstLine(error)),
                             kWarningTimeoutMs);
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
    const Scene scene = m_viewport->currentScene();
    m_sceneDock->showScene(scene, m_viewport->meshInfo());
    m_performanceDock->showAutoDetail(
        !scene.objects.empty()
        && std::all_of(scene.objects.begin(), scene.objects.end(),
                       [](const SceneObject &o) { return o.autoDetail; }));
}

void MainWindow::setScenePath(const QString &path, const QString &title)
{
    m_scenePath = path;
    m_fileMenu->rememberFolderOf(path);
    QString name = title;
    if (name.isEmpty())
        name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    setWindowTitle(tr("%1 — PhongLab").arg(name));
}

Result<> MainWindow::exportImage(const QString &path, const QSize &size)
{
    const QImage image = m_viewport->renderImage(size);
    if (image.isNull())
        return fail(tr("Cannot render a %1×%2 image").arg(size.width()).arg(size.height()));
    if (!image.save(path, "PNG"))
        return fail(tr("Cannot write %1").arg(path));
    return {};
}

void MainWindow::warn(const QString &title, const QString &message)
{
    openWarning(this, title, message);
}

} // namespace phonglab
