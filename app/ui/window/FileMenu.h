#pragma once
#include <QObject>
#include <QStringList>

class QMenu;

namespace phonglab {

class MainWindow;
class RecentFiles;

// The File menu: the dialogs in front of SceneDocument's open, save and
// export (which work without them, for tests and start-up), the recent files, the
// shipped example scenes (ExamplesMenu), and what each says when it fails.
class FileMenu : public QObject
{
    Q_OBJECT

public:
    FileMenu(MainWindow *window, QMenu *menu);

    RecentFiles *recentFiles() const { return m_recentFiles; }
    // File → Open, File → Recent and a drop: opens, or says in a dialog why
    // not (the current scene stays).
    void openOrExplain(const QStringList &paths);
    // The file dialogs start in the folder of the last file opened or saved.
    void rememberFolderOf(const QString &path);

private:
    void chooseAndOpenScene();
    void chooseAndOpenMeshes();
    // A WebGL project's page or script: its program that lights (asked
    // which where there are several) into the Shaders dock. The dock's own
    // Open… comes here too: one way to open shaders.
    void chooseAndOpenShaders();
    void chooseAndOpenProject();
    void chooseAndOpenProjectFolder();
    void openProject(const QString &folder, const QString &page);
    // File → Run the Page: the project last opened (else one chosen), run
    // in the browser with the scene's "page" (ui/check/PageRunDialog).
    void runThePage();
    bool mayDiscardShaderEdits();
    void explainMissingRecentFile(const QString &path);
    void saveToCurrentFile();
    void chooseAndSave();
    void chooseAndExportImage();
    void warnCannotSave(const QString &path, const QString &error);
    QString dialogFolder() const;

    MainWindow *m_window = nullptr;
    RecentFiles *m_recentFiles = nullptr;
    QString m_lastFolder;
    QString m_projectFolder; // the WebGL project last opened
    QString m_projectPage;   // its page, relative; empty: index.html or its only page
};

} // namespace phonglab
