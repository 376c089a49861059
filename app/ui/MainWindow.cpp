#include "MainWindow.h"

#include "Viewport.h"
#include "core/SceneJson.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

namespace phonglab {

namespace {

constexpr int kWarningTimeoutMs = 10000;
const QString kSceneFilter = QStringLiteral("PhongLab scenes (*.json);;All files (*)");

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

} // namespace

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_viewport(new Viewport(this))
{
    setCentralWidget(m_viewport);
    createMenus();
    createStatusBar();
    connect(m_viewport, &Viewport::frameRendered, this, &MainWindow::showFrameStats);
    connect(m_viewport, &Viewport::glRendererChanged, m_rendererLabel, &QLabel::setText);
    // Queued: the error is raised from inside initializeGL / paintGL, where a
    // dialog must not be opened.
    connect(m_viewport, &Viewport::renderError, this, &MainWindow::showRenderError, Qt::QueuedConnection);
    setScenePath({});
}

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QAction *open = file->addAction(tr("&Open Scene…"), this, &MainWindow::chooseAndOpenScene);
    open->setShortcut(QKeySequence::Open);
    file->addSeparator();
    QAction *save = file->addAction(tr("&Save Scene"), this, &MainWindow::saveSceneToCurrentFile);
    save->setShortcut(QKeySequence::Save);
    QAction *saveAs = file->addAction(tr("Save Scene &As…"), this, &MainWindow::chooseAndSaveScene);
    saveAs->setShortcut(QKeySequence(tr("Ctrl+Shift+S")));
    file->addSeparator();
    QAction *quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence(tr("Ctrl+Q")));
    quit->setMenuRole(QAction::QuitRole);

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
}

void MainWindow::createStatusBar()
{
    m_frameLabel = new QLabel(this);
    m_rendererLabel = new QLabel(tr("OpenGL not started"), this);
    statusBar()->addPermanentWidget(m_frameLabel);
    statusBar()->addPermanentWidget(m_rendererLabel);
}

bool MainWindow::openScene(const QString &path, QString *error)
{
    const SceneLoadResult loaded = loadSceneFile(path);
    QString reason = loaded.error;
    if (!loaded.ok() || !m_viewport->setScene(*loaded.scene, &reason)) {
        if (error)
            *error = reason;
        return false;
    }
    setScenePath(path);
    if (!loaded.warnings.isEmpty())
        statusBar()->showMessage(loaded.warnings.join(QStringLiteral("; ")), kWarningTimeoutMs);
    else
        statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(path).fileName()), kWarningTimeoutMs);
    return true;
}

bool MainWindow::saveScene(const QString &path, QString *error)
{
    if (!saveSceneFile(rebasedOnto(m_viewport->currentScene(), path), path, error))
        return false;
    setScenePath(path);
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), kWarningTimeoutMs);
    return true;
}

void MainWindow::chooseAndOpenScene()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Scene"), dialogFolder(), kSceneFilter);
    if (path.isEmpty())
        return;
    QString error;
    if (!openScene(path, &error))
        warn(tr("Cannot open scene"),
             tr("%1\n\n%2\n\nThe current scene is still open.").arg(QDir::toNativeSeparators(path), error));
}

void MainWindow::saveSceneToCurrentFile()
{
    if (!isWritableLocation(m_scenePath)) {
        chooseAndSaveScene();
        return;
    }
    QString error;
    if (!saveScene(m_scenePath, &error))
        warn(tr("Cannot save scene"), tr("%1\n\n%2").arg(QDir::toNativeSeparators(m_scenePath), error));
}

void MainWindow::chooseAndSaveScene()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Save Scene As"), dialogFolder(), kSceneFilter);
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    QString error;
    // saveSceneFile writes atomically: on failure the old file and the scene
    // in the window are both untouched, so the user can retry elsewhere.
    if (!saveScene(path, &error))
        warn(tr("Cannot save scene"), tr("%1\n\n%2").arg(QDir::toNativeSeparators(path), error));
}

void MainWindow::showFrameStats(double milliseconds, qint64 triangles)
{
    m_frameLabel->setText(tr("%1 ms · %2 triangles")
                              .arg(milliseconds, 0, 'f', 2)
                              .arg(QLocale().toString(triangles)));
}

void MainWindow::showRenderError(const QString &message)
{
    statusBar()->showMessage(tr("Rendering failed: %1").arg(message.section(QLatin1Char('\n'), 0, 0)));
    // Non-blocking, so a broken GL setup never stalls the event loop.
    auto *box = new QMessageBox(QMessageBox::Critical, tr("Rendering failed"), message, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::setScenePath(const QString &path)
{
    m_scenePath = path;
    const QString name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    setWindowTitle(tr("%1 — PhongLab").arg(name));
}

QString MainWindow::dialogFolder() const
{
    return isWritableLocation(m_scenePath) ? QFileInfo(m_scenePath).absolutePath() : QDir::homePath();
}

void MainWindow::warn(const QString &title, const QString &message)
{
    QMessageBox::warning(this, title, message);
}

} // namespace phonglab
