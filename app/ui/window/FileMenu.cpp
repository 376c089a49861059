#include "FileMenu.h"
#include "ui/shaders/ShaderFileSet.h"

#include "ExamplesMenu.h"
#include "MainWindow.h"
#include "RecentFiles.h"
#include "SceneDocument.h"
#include "WarningBox.h"
#include "core/project/ProjectPrograms.h"
#include "core/scene/ResourcePaths.h"
#include "core/scene/SceneJson.h"
#include "core/scene/ScenePaths.h"
#include "ui/check/PageRunDialog.h"
#include "ui/scene/FileTypes.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/viewport/Viewport.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>

namespace phonglab {

namespace {

constexpr int kMessageTimeoutMs = 10000;
constexpr int kLargestImageSide = 16384;
} // namespace

FileMenu::FileMenu(MainWindow *window, QMenu *menu)
    : QObject(window)
    , m_window(window)
{
    QAction *open = menu->addAction(tr("&Open Scene…"), this, &FileMenu::chooseAndOpenScene);
    open->setShortcut(QKeySequence::Open);
    QAction *openMesh = menu->addAction(tr("Open &Mesh…"), this, &FileMenu::chooseAndOpenMeshes);
    openMesh->setShortcut(QKeySequence(tr("Ctrl+Shift+O")));
    menu->addAction(tr("Open S&hader…"), this, &FileMenu::chooseAndOpenShaders);
    connect(window->shaderDock(), &ShaderDock::openRequested, this,
            &FileMenu::chooseAndOpenShaders);
    menu->addAction(tr("Open &Project…"), this, &FileMenu::chooseAndOpenProject);
    menu->addAction(tr("Open Project &Folder…"), this, &FileMenu::chooseAndOpenProjectFolder);
    menu->addAction(tr("&Run the Page…"), this, &FileMenu::runThePage)
        ->setObjectName(QStringLiteral("runThePage"));
    m_recentFiles = new RecentFiles(menu->addMenu(tr("&Recent")), this);
    connect(m_recentFiles, &RecentFiles::fileChosen, this,
            [this](const QString &path) { openOrExplain({path}); });
    connect(m_recentFiles, &RecentFiles::missingFileChosen, this,
            &FileMenu::explainMissingRecentFile);
    auto *examples = new ExamplesMenu(menu->addMenu(tr("E&xamples")), this);
    connect(examples, &ExamplesMenu::sceneChosen, this,
            [this](const QString &path) { openOrExplain({path}); });
    menu->addSeparator();
    QAction *save = menu->addAction(tr("&Save Scene"), this, &FileMenu::saveToCurrentFile);
    save->setShortcut(QKeySequence::Save);
    QAction *saveAs = menu->addAction(tr("Save Scene &As…"), this, &FileMenu::chooseAndSave);
    saveAs->setShortcut(QKeySequence(tr("Ctrl+Shift+S")));
    menu->addAction(tr("&Export Image…"), this, &FileMenu::chooseAndExportImage);
    menu->addSeparator();
    QAction *quit = menu->addAction(tr("&Quit"), window, &QWidget::close);
    quit->setShortcut(QKeySequence(tr("Ctrl+Q")));
    quit->setMenuRole(QAction::QuitRole);
}

void FileMenu::openOrExplain(const QStringList &paths)
{
    const Result<> opened = m_window->document()->openFiles(paths);
    if (opened)
        return;
    m_window->statusBar()->showMessage(tr("Cannot open: %1").arg(firstLine(opened.error())),
                                       kMessageTimeoutMs);
    openWarning(m_window, tr("Cannot open"),
                tr("%1\n\nThe current scene is still open.").arg(opened.error()));
}

void FileMenu::rememberFolderOf(const QString &path)
{
    if (isWritableLocation(path))
        m_lastFolder = QFileInfo(path).absolutePath();
}

void FileMenu::chooseAndOpenScene()
{
    const QString path =
        QFileDialog::getOpenFileName(m_window, tr("Open Scene"), dialogFolder(), sceneFileFilter());
    if (!path.isEmpty())
        openOrExplain({path});
}

void FileMenu::chooseAndOpenShaders()
{
    const QStringList paths = QFileDialog::getOpenFileNames(m_window, tr("Open Shader"),
                                                            dialogFolder(), shaderFileFilter());
    if (paths.isEmpty() || !mayDiscardShaderEdits())
        return;
    rememberFolderOf(paths.front());
    if (const Result<> opened = m_window->document()->openShaderFiles(paths); !opened)
        openWarning(m_window, tr("Cannot open"), opened.error());
}

void FileMenu::chooseAndOpenProject()
{
    const QString page =
        QFileDialog::getOpenFileName(m_window, tr("Open WebGL Project"), dialogFolder(),
                                     tr("WebGL projects (*.html *.htm *.js *.mjs);;All files (*)"));
    if (page.isEmpty())
        return;
    rememberFolderOf(page);
    // The page's folder: its scripts and shader files are the project too.
    openProject(QFileInfo(page).absolutePath(), page);
}

void FileMenu::chooseAndOpenProjectFolder()
{
    const QString folder = QFileDialog::getExistingDirectory(
        m_window, tr("Open WebGL Project Folder"), dialogFolder());
    if (folder.isEmpty())
        return;
    rememberFolderOf(QDir(folder).filePath(QStringLiteral(".")));
    openProject(folder, {});
}

// The project in `folder`; of several programs that light the user picks
// one, the one `page` holds offered first.
void FileMenu::openProject(const QString &folder, const QString &page)
{
    m_projectFolder = folder;
    m_projectPage = page.isEmpty() ? QString() : QFileInfo(page).fileName();
    const Project project = readProject(folder);
    QString name;
    if (const std::vector<const ProjectProgram *> lit = litPrograms(project); lit.size() > 1) {
        QStringList names;
        for (const ProjectProgram *p : lit)
            names << p->name;
        bool ok = false;
        name = QInputDialog::getItem(m_window, tr("Open WebGL Project"),
                                     tr("The project has several programs that light. Which one?"),
                                     names, int(programOfPage(lit, page)), false, &ok);
        if (!ok)
            return;
    }
    const Result<ProjectProgram> chosen = chooseProgram(project, name);
    if (chosen && !mayDiscardShaderEdits())
        return;
    const Result<> opened = chosen ? m_window->document()->openShaders(
                                shaderLocator(chosen->vertex), shaderLocator(chosen->fragment))
                                   : Result<>(fail(chosen.error()));
    if (!opened) {
        openWarning(m_window, tr("Cannot open"), opened.error());
        return;
    }
    m_window->statusBar()->showMessage(
        tr("Opened %1 of %2")
            .arg(chosen->name, QFileInfo(page.isEmpty() ? folder : page).fileName()),
        kMessageTimeoutMs);
}

void FileMenu::runThePage()
{
    QString folder = m_projectFolder;
    if (folder.isEmpty())
        folder = QFileDialog::getExistingDirectory(m_window, tr("Run a WebGL Project's Page"),
                                                   dialogFolder());
    if (folder.isEmpty())
        return;
    PageRequest request;
    request.run.folders.project = folder;
    request.run.pageFile = m_projectPage;
    if (const QString scene = m_window->document()->path(); !scene.isEmpty())
        if (const SceneLoadResult loaded = loadSceneFile(scene); loaded.ok())
            takeScenePage(&request, loaded.scene->page, loaded.scene->baseDir);
    auto *dialog = new PageRunDialog(request, m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
}

bool FileMenu::mayDiscardShaderEdits()
{
    return !m_window->shaderDock()->hasUnsavedChanges()
        || QMessageBox::question(m_window, tr("Unsaved changes"),
                                 tr("The shaders have unsaved changes. Discard them?"),
                                 QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel)
        == QMessageBox::Discard;
}

void FileMenu::chooseAndOpenMeshes()
{
    const QStringList paths =
        QFileDialog::getOpenFileNames(m_window, tr("Open Mesh"), dialogFolder(), meshFileFilter());
    if (!paths.isEmpty())
        openOrExplain(paths);
}

void FileMenu::explainMissingRecentFile(const QString &path)
{
    openWarning(m_window, tr("File not found"),
                tr("%1\n\nThe file no longer exists; it was removed from the recent files.")
                    .arg(QDir::toNativeSeparators(path)));
}

void FileMenu::saveToCurrentFile()
{
    const QString path = m_window->document()->path();
    if (!isWritableLocation(path) || isShippedScene(path)) {
        chooseAndSave();
        return;
    }
    if (const Result<> saved = m_window->document()->save(path); !saved)
        warnCannotSave(path, saved.error());
}

void FileMenu::chooseAndSave()
{
    QString path = QFileDialog::getSaveFileName(m_window, tr("Save Scene As"), dialogFolder(),
                                                sceneFileFilter());
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    // saveSceneFile writes atomically: on failure the old file and the scene
    // in the window are both untouched, so the user can retry elsewhere.
    if (const Result<> saved = m_window->document()->save(path); !saved)
        warnCannotSave(path, saved.error());
}

void FileMenu::warnCannotSave(const QString &path, const QString &error)
{
    openWarning(m_window, tr("Cannot save scene"),
                tr("%1\n\n%2").arg(QDir::toNativeSeparators(path), error));
}

void FileMenu::chooseAndExportImage()
{
    const Viewport *viewport = m_window->viewport();
    const QSize shown = viewport->size() * viewport->devicePixelRatioF();
    bool ok = false;
    const int width = QInputDialog::getInt(m_window, tr("Export Image"), tr("Width (pixels):"),
                                           shown.width(), 1, kLargestImageSide, 1, &ok);
    if (!ok)
        return;
    const int height = QInputDialog::getInt(m_window, tr("Export Image"), tr("Height (pixels):"),
                                            shown.height(), 1, kLargestImageSide, 1, &ok);
    if (!ok)
        return;
    const QString path = QFileDialog::getSaveFileName(m_window, tr("Export Image"), dialogFolder(),
                                                      tr("PNG images (*.png)"));
    if (path.isEmpty())
        return;
    if (const Result<> exported = m_window->document()->exportImage(path, {width, height});
        !exported)
        openWarning(m_window, tr("Export Image"), exported.error());
    else
        m_window->statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()),
                                           kMessageTimeoutMs);
}

QString FileMenu::dialogFolder() const
{
    return m_lastFolder.isEmpty() ? QDir::homePath() : m_lastFolder;
}

} // namespace phonglab
