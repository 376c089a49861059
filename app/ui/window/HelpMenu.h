#pragma once
#include <QObject>
#include <QPointer>

class QAction;
class QMenu;

namespace phonglab {

class AboutDialog;
class DocumentationBrowser;
class MainWindow;
class ShortcutsDialog;

// The Help menu: the shipped documentation (DocumentationBrowser), the
// keyboard shortcuts read from the window's actions (ShortcutsDialog), About
// PhongLab (AboutDialog: versions, the OpenGL renderer) and About Qt. None of
// its windows blocks the editor.
class HelpMenu : public QObject
{
    Q_OBJECT

public:
    HelpMenu(MainWindow *window, QMenu *menu);

    QAction *documentationAction() const { return m_documentation; }
    QAction *shortcutsAction() const { return m_shortcuts; }
    QAction *aboutAction() const { return m_about; }

    // What the actions open, while open (null before, or once closed).
    DocumentationBrowser *documentationBrowser() const;
    ShortcutsDialog *shortcutsDialog() const;
    AboutDialog *aboutDialog() const;

    // What Documentation says when no folder holds the docs: where it looked.
    static QString missingDocumentationMessage(const QStringList &searched);

private:
    void showDocumentation();
    void showShortcuts();
    void showAbout();

    MainWindow *m_window = nullptr;
    QAction *m_documentation = nullptr;
    QAction *m_shortcuts = nullptr;
    QAction *m_about = nullptr;
    QPointer<DocumentationBrowser> m_browser;
    QPointer<ShortcutsDialog> m_shortcutsDialog;
    QPointer<AboutDialog> m_aboutDialog;
};

} // namespace phonglab
