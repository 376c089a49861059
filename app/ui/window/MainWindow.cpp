#include "MainWindow.h"

#include "DefaultLayout.h"
#include "FileMenu.h"
#include "HelpMenu.h"
#include "LoadProgressWidget.h"
#include "SceneDocument.h"
#include "ViewMenu.h"
#include "WarningBox.h"
#include "core/support/Language.h"
#include "ui/check/CheckMarks.h"
#include "ui/check/LiveCheck.h"
#include "ui/check/PixelInspectorDock.h"
#include "ui/performance/PerformanceDock.h"
#include "ui/scene/LightsDock.h"
#include "ui/scene/MaterialDock.h"
#include "ui/scene/ObjectDock.h"
#include "ui/scene/SceneDock.h"
#include "ui/scene/SceneEditDockSet.h"
#include "ui/scene/SceneLoadJob.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderFileDialogs.h"
#include "ui/uniforms/UniformsDock.h"
#include "ui/viewport/DetailLevelLabel.h"
#include "ui/viewport/FrameStatsLabel.h"
#include "ui/viewport/Viewport.h"

#include <QCloseEvent>
#include <QLabel>
#include <QMenuBar>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>

#include <algorithm>
#include <utility>

namespace phonglab {

MainWindow::MainWindow(QWidget *parent, const StartupOptions &options)
    : QMainWindow(parent)
    , m_options(options)
    , m_viewport(new Viewport(this, !options.presentOnGuiThread))
    , m_sceneDock(new SceneDock(this))
    , m_shaderDock(new ShaderDock(this))
{
    setCentralWidget(m_viewport);
    addDockWidget(Qt::LeftDockWidgetArea, m_sceneDock);
    addDockWidget(Qt::RightDockWidgetArea, m_shaderDock);
    createShaderDock();
    createDocument();
    createUniformsDock();
    createPerformanceDock();
    m_editDocks = new SceneEditDockSet(this, m_viewport);
    m_editDocks->addEditActions(menuBar()->addMenu(tr("&Edit")));
    // Before the status bar: the verdict comes first among its permanent
    // widgets, where a long diagnosis pushes nothing else out of sight.
    m_liveCheck = new LiveCheck(this, m_viewport, m_liveShaders);
    new ViewMenu(this, menuBar()->addMenu(tr("&View")));
    new HelpMenu(this, menuBar()->addMenu(tr("&Help"))); // last: after every other menu
    createStatusBar();
    connectLoading();
    m_liveCheck->pauseWhileLoading(m_document->loadJob());
    connect(m_uniformsDock, &UniformsDock::valueWritten, m_liveCheck, &LiveCheck::frameChanged);
    connectCheck();
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
            m_performanceDock,
            m_liveCheck->verdictDock()};
}

void MainWindow::resetLayout()
{
    m_shaderDock->ensurePolished();
    const bool wasLayingOut = std::exchange(m_layingOut, true);
    applyDefaultLayout(*this, docks(), m_shaderDock->sizeHint().width());
    m_layingOut = wasLayingOut;
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
    new ShaderFileDialogs(m_shaderDock);
    connect(m_liveShaders, &LiveShaderController::statusMessage, statusBar(),
            &QStatusBar::showMessage);
    connect(m_viewport, &Viewport::sceneChanged, this,
            [this] { m_liveShaders->shading()->followScene(m_viewport->currentScene().shading); });
}

// The File menu first, in the menu bar as on the screen: the document
// remembers what it opens in its recent files.
void MainWindow::createDocument()
{
    m_fileMenu = new FileMenu(this, menuBar()->addMenu(tr("&File")));
    m_recentFiles = m_fileMenu->recentFiles();
    m_document = new SceneDocument(this, m_viewport, m_shaderDock, m_liveShaders, m_recentFiles);
    connect(m_document, &SceneDocument::folderUsed, m_fileMenu, &FileMenu::rememberFolderOf);
    m_document->offerRecovery(m_options.recoveryAnswer, m_options.typeAfterStart);
}

// A clean exit forgets the recovery journal: unsaved shaders are offered
// for saving first.
void MainWindow::closeEvent(QCloseEvent *event)
{
    if (m_document->confirmClose()) {
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
    const bool wasLayingOut = std::exchange(m_layingOut, true);
    const bool stateOk = !state.isEmpty() && restoreState(state, kWindowStateVersion);
    m_layingOut = wasLayingOut;
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
// The check's findings where the student works: a uniform to place in the
// Uniforms dock, a mistake on its line in the editor.
void MainWindow::connectCheck()
{
    connect(m_liveCheck, &LiveCheck::uniformToPlace, m_uniformsDock, &UniformsDock::showUniform);
    // Once the dock brought forward is laid out at the front.
    const auto giveRoom = [this](QDockWidget *dock) {
        QTimer::singleShot(0, dock, [this, dock] { giveRoomUnderTheCode(*this, docks(), dock); });
    };
    connect(m_liveCheck, &LiveCheck::dockBroughtForward, this, giveRoom);
    // A tab under the code chosen by the user shows its contents, not three
    // rows of them; the layout's own choices leave the code its room.
    connect(this, &QMainWindow::tabifiedDockWidgetActivated, this,
            [this, giveRoom](QDockWidget *dock) {
                if (!m_layingOut)
                    giveRoom(dock);
            });
    connect(m_liveCheck, &LiveCheck::uniformToPlace, this,
            [this, giveRoom] { giveRoom(m_uniformsDock); });
    connect(m_liveCheck->verdictDock(), &VerdictDock::lineChosen, this,
            [this](ShaderStage stage, int line) { m_shaderDock->goTo(stage, line, 0); });
    connect(m_liveCheck, &LiveCheck::checked, this, [this](const CheckedFrame &result) {
        QStringList unplaced;
        for (const UnboundUniform &u : result.unbound)
            unplaced << u.name;
        m_uniformsDock->markUnplaced(unplaced);
        const CheckMarks marks = checkMarks(result);
        QByteArray vertex;
        QByteArray fragment;
        for (const ShaderStageText &s : result.outcome.stages)
            (s.vertex ? vertex : fragment) = s.text.toUtf8();
        m_shaderDock->showCheckMarks(marks.vertex, vertex, marks.fragment, fragment);
    });
}

void MainWindow::createPerformanceDock()
{
    m_performanceDock = new PerformanceDock(m_viewport, this);
    addDockWidget(Qt::LeftDockWidgetArea, m_performanceDock);
    connect(m_performanceDock, &PerformanceDock::applyFitRequested, m_document,
            &SceneDocument::applyFit);
    connect(m_performanceDock, &PerformanceDock::autoDetailRequested, m_document,
            &SceneDocument::setAutoDetail);
    new DetailLevelLabel(m_viewport);
}

void MainWindow::createStatusBar()
{
    m_loadProgress = new LoadProgressWidget(m_document->loadJob(), this);
    m_rendererLabel = new QLabel(tr("OpenGL not started"), this);
    statusBar()->addPermanentWidget(m_loadProgress);
    statusBar()->addPermanentWidget(new FrameStatsLabel(m_viewport, statusBar()));
    statusBar()->addPermanentWidget(m_rendererLabel);
}

// The Scene dock follows the scene shown; after a load that ended without a
// new one, what is shown still (its normals control goes back to it).
void MainWindow::connectLoading()
{
    connect(m_viewport, &Viewport::sceneChanged, this, &MainWindow::refreshSceneDock);
    SceneLoadJob *job = m_document->loadJob();
    connect(job, &SceneLoadJob::failed, this, &MainWindow::refreshSceneDock);
    // A load superseded by a newer one leaves the dock showing the newer request.
    connect(job, &SceneLoadJob::cancelled, this, [this, job] {
        if (!job->isRunning())
            refreshSceneDock();
    });
    // Queued: the dock is rebuilding itself or its editor is mid-signal when a
    // drop or an edit arrives; both are handled once that is over.
    connect(m_viewport, &Viewport::filesDropped, m_fileMenu, &FileMenu::openOrExplain,
            Qt::QueuedConnection);
    connect(m_sceneDock, &SceneDock::normalsChangeRequested, m_document,
            &SceneDocument::changeNormals, Qt::QueuedConnection);
}

void MainWindow::showRenderError(const QString &message)
{
    statusBar()->showMessage(tr("Rendering failed: %1").arg(firstLine(message)));
    openWarning(this, tr("Rendering failed"), message, QMessageBox::Critical);
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

} // namespace phonglab
