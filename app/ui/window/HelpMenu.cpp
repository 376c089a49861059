#include "HelpMenu.h"

#include "MainWindow.h"
#include "WarningBox.h"
#include "ui/help/AboutDialog.h"
#include "ui/help/DocumentationBrowser.h"
#include "ui/help/DocumentationFiles.h"
#include "ui/help/ShortcutsDialog.h"
#include "ui/viewport/Viewport.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QMenu>

namespace phonglab {

namespace {

// Brought to the front when open already; `make` opens a new one otherwise.
template <typename Window, typename Make> Window *showOrRaise(QPointer<Window> &window, Make make)
{
    if (!window) {
        window = make();
        window->setAttribute(Qt::WA_DeleteOnClose);
    }
    window->show();
    window->raise();
    window->activateWindow();
    return window;
}

} // namespace

HelpMenu::HelpMenu(MainWindow *window, QMenu *menu)
    : QObject(window)
    , m_window(window)
{
    m_documentation = menu->addAction(tr("&Documentation"), this, &HelpMenu::showDocumentation);
    m_documentation->setShortcut(QKeySequence::HelpContents);
    m_shortcuts = menu->addAction(tr("&Keyboard Shortcuts"), this, &HelpMenu::showShortcuts);
    menu->addSeparator();
    m_about = menu->addAction(tr("&About PhongLab"), this, &HelpMenu::showAbout);
    m_about->setMenuRole(QAction::AboutRole);
    QAction *aboutQt = menu->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
    aboutQt->setMenuRole(QAction::AboutQtRole);
}

DocumentationBrowser *HelpMenu::documentationBrowser() const
{
    return m_browser;
}

ShortcutsDialog *HelpMenu::shortcutsDialog() const
{
    return m_shortcutsDialog;
}

AboutDialog *HelpMenu::aboutDialog() const
{
    return m_aboutDialog;
}

QString HelpMenu::missingDocumentationMessage(const QStringList &searched)
{
    QStringList folders;
    for (const QString &folder : searched)
        folders << QStringLiteral("  ") + QDir::toNativeSeparators(folder);
    return tr("The documentation (README.md and docs/*.md) is in none of these folders:\n\n%1\n\n"
              "Set PHONGLAB_DOC_DIR to the folder that holds it.")
        .arg(folders.join(QLatin1Char('\n')));
}

void HelpMenu::showDocumentation()
{
    const QString first = m_window->startupOptions().documentationFolder;
    const QString folder = documentationFolder(first);
    if (folder.isEmpty()) {
        openWarning(m_window, tr("Documentation not found"),
                    missingDocumentationMessage(documentationSearchFolders(first)));
        return;
    }
    showOrRaise(m_browser, [&] { return new DocumentationBrowser(folder, m_window); });
}

// A new list each time it opens, so actions added since are in it.
void HelpMenu::showShortcuts()
{
    if (m_shortcutsDialog)
        m_shortcutsDialog->refresh();
    showOrRaise(m_shortcutsDialog, [this] { return new ShortcutsDialog(m_window); });
}

// The renderer can change while the app runs (the view moved to another
// screen's context), so the dialog is made anew each time.
void HelpMenu::showAbout()
{
    delete m_aboutDialog;
    showOrRaise(m_aboutDialog, [this] {
        return new AboutDialog(m_window->viewport()->glContext().glRendererName(), m_window);
    });
}

} // namespace phonglab
