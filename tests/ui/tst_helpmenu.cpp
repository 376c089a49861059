// The Help menu in the real window: Documentation opens the shipped docs
// offline and follows their links; Keyboard Shortcuts lists every action
// with a key, read from the actions each time it opens (an action added
// later shows up); About names the versions and the OpenGL renderer the view
// really got.
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "ui/help/AboutDialog.h"
#include "ui/help/DocumentView.h"
#include "ui/help/DocumentationBrowser.h"
#include "ui/help/DocumentationFiles.h"
#include "ui/help/ShortcutsDialog.h"
#include "ui/viewport/CurrentContext.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/HelpMenu.h"
#include "ui/window/MainWindow.h"
#include "ui/window/StartupOptions.h"

#include <OpenMesh/Core/System/config.h>

#include <QAction>
#include <QDir>
#include <QIcon>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTreeWidget>

#include <algorithm>

using namespace phonglab;
using namespace phonglab::test;

namespace {

const QString kSeparator = QStringLiteral(" › ");

QString keys(QKeySequence::StandardKey key)
{
    return QKeySequence(key).toString(QKeySequence::NativeText);
}

const ShortcutsDialog::Entry *entryFor(const QList<ShortcutsDialog::Entry> &entries,
                                       const QString &command)
{
    for (const ShortcutsDialog::Entry &entry : entries)
        if (entry.command == command)
            return &entry;
    return nullptr;
}

// The window a widget is part of; a menu is a window of its own, and
// belongs to the one its menu bar is in.
const QWidget *ownerWindow(const QWidget *widget)
{
    while (qobject_cast<const QMenu *>(widget) && widget->parentWidget())
        widget = widget->parentWidget();
    return widget->window();
}

// Every action of the window that has a key and is on one of its widgets
// (found by ownership, not by the menus the dialog walks).
QSet<const QAction *> actionsWithKeys(const QMainWindow &window)
{
    QSet<const QAction *> found;
    for (const QAction *action : window.findChildren<QAction *>()) {
        if (action->shortcuts().isEmpty())
            continue;
        for (const QObject *object : action->associatedObjects())
            if (const auto *widget = qobject_cast<const QWidget *>(object);
                widget && ownerWindow(widget) == &window)
                found.insert(action);
    }
    return found;
}

// Where in the page `text` (a link's text) is drawn, in viewport coordinates.
QPoint positionOfText(DocumentView *view, const QString &text)
{
    const QTextCursor found = view->document()->find(text);
    if (found.isNull())
        return {-1, -1};
    QTextCursor middle(view->document());
    middle.setPosition((found.selectionStart() + found.selectionEnd()) / 2);
    view->setTextCursor(middle);
    view->ensureCursorVisible();
    return view->cursorRect(middle).center();
}

// For a person to look at (PHONGLAB_TEST_ARTIFACTS=dir), as tst_mainwindow does.
void saveArtifact(const QString &name, QWidget *widget)
{
    const QString dir = qEnvironmentVariable("PHONGLAB_TEST_ARTIFACTS");
    if (!dir.isEmpty() && QDir().mkpath(dir))
        widget->grab().save(QDir(dir).filePath(name));
}

void writeFile(const QString &path, const QByteArray &text)
{
    QVERIFY(QDir().mkpath(QFileInfo(path).path()));
    QFile file(path);
    QVERIFY2(file.open(QIODevice::WriteOnly), qPrintable(file.errorString()));
    file.write(text);
}

} // namespace

class TestHelpMenu : public QObject, private UiTestWindow
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase() { m_window.reset(); }

    void helpMenuHasItsActions();
    void iconIsEmbedded();
    void shortcutsListEveryActionWithAKey();
    void shortcutsAreReadWhenOpened();
    void aboutNamesVersionsAndRenderer();
    void documentationOpensReadmeAndFollowsALink();
    void documentationFolderComesFromTheEnvironment();
    void germanRunOpensTheGermanPages();
    void linkToAMissingFileSaysSo();

private:
    HelpMenu *helpMenu() const { return m_window->findChild<HelpMenu *>(); }
};

void TestHelpMenu::initTestCase()
{
    m_env.isolate();
    openWindow(sourcePath(QStringLiteral("assets/scenes/sphere.json")), {800, 600});
    QVERIFY(!QTest::currentTestFailed());
    QVERIFY(helpMenu());
}

void TestHelpMenu::helpMenuHasItsActions()
{
    const QList<QAction *> menus = m_window->menuBar()->actions();
    QVERIFY(!menus.isEmpty());
    QCOMPARE(menus.back()->text(), QStringLiteral("&Help")); // the last menu, as everywhere
    const QList<QAction *> items = menus.back()->menu()->actions();
    for (QAction *action : {helpMenu()->documentationAction(), helpMenu()->shortcutsAction(),
                            helpMenu()->aboutAction()})
        QVERIFY2(items.contains(action), qPrintable(action->text()));
    QCOMPARE(helpMenu()->documentationAction()->text(), QStringLiteral("&Documentation"));
    QCOMPARE(helpMenu()->shortcutsAction()->text(), QStringLiteral("&Keyboard Shortcuts"));
    QCOMPARE(helpMenu()->aboutAction()->text(), QStringLiteral("&About PhongLab"));
    QCOMPARE(helpMenu()->documentationAction()->shortcut(),
             QKeySequence(QKeySequence::HelpContents));
    QVERIFY(std::any_of(items.begin(), items.end(),
                        [](const QAction *a) { return a->menuRole() == QAction::AboutQtRole; }));
}

// GuiMain sets it as the window icon; it must load (Qt's svg plugin).
void TestHelpMenu::iconIsEmbedded()
{
    const QIcon icon(QStringLiteral(":/packaging/org.phonglab.PhongLab.svg"));
    QVERIFY(!icon.pixmap(64, 64).isNull());
}

void TestHelpMenu::shortcutsListEveryActionWithAKey()
{
    helpMenu()->shortcutsAction()->trigger();
    ShortcutsDialog *dialog = helpMenu()->shortcutsDialog();
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    const QList<ShortcutsDialog::Entry> entries = dialog->entries();
    QSet<const QAction *> listed;
    for (const ShortcutsDialog::Entry &entry : entries)
        listed.insert(entry.action);
    const QSet<const QAction *> expected = actionsWithKeys(*m_window);
    for (const QAction *action : expected - listed)
        QVERIFY2(false, qPrintable("not listed: " + action->text()));
    for (const QAction *action : listed - expected)
        QVERIFY2(false, qPrintable("listed, yet not the window's: " + action->text()));
    QCOMPARE(dialog->table()->topLevelItemCount(), entries.size());

    // The menu path, the keys as the platform writes them, where they work.
    const ShortcutsDialog::Entry *open = entryFor(entries, "File" + kSeparator + "Open Scene…");
    QVERIFY(open);
    QCOMPARE(open->keys, keys(QKeySequence::Open));
    QCOMPARE(open->scope, QStringLiteral("anywhere in the window"));
    const ShortcutsDialog::Entry *reset = entryFor(entries, "View" + kSeparator + "Reset Camera");
    QVERIFY(reset);
    QCOMPARE(reset->keys, QStringLiteral("R, Home"));
    QVERIFY2(reset->scope.contains(QStringLiteral("3D view")), qPrintable(reset->scope));
    // Keys outside the menus: the check toolbar's and the Shaders dock's.
    const ShortcutsDialog::Entry *inspect =
        entryFor(entries, "Check toolbar" + kSeparator + "Inspect");
    QVERIFY(inspect);
    QCOMPARE(inspect->keys, QStringLiteral("I"));
    QVERIFY(std::any_of(entries.begin(), entries.end(), [](const ShortcutsDialog::Entry &e) {
        return e.keys == QStringLiteral("F5") && e.scope.contains(QStringLiteral("Shaders dock"));
    }));
    // What the dialog shows is the same list.
    const QTreeWidgetItem *first = dialog->table()->topLevelItem(0);
    QCOMPARE(first->text(0), entries.front().command);
    QCOMPARE(first->text(1), entries.front().keys);
    saveArtifact(QStringLiteral("help-shortcuts.png"), dialog);
    dialog->close();
}

// Proof the list is generated: an action added after start is listed the
// next time the dialog opens, and refreshed while it is open.
void TestHelpMenu::shortcutsAreReadWhenOpened()
{
    QMenu *tools = m_window->menuBar()->addMenu(QStringLiteral("&Tools"));
    QAction *added = tools->addMenu(QStringLiteral("&Deeper"))->addAction(QStringLiteral("&Frob"));
    added->setShortcut(QKeySequence(QStringLiteral("Ctrl+Alt+F")));
    auto *windowLevel = new QAction(QStringLiteral("Quux"), m_window.get());
    windowLevel->setShortcut(QKeySequence(Qt::Key_F9));
    m_window->addAction(windowLevel);

    helpMenu()->shortcutsAction()->trigger();
    ShortcutsDialog *dialog = helpMenu()->shortcutsDialog();
    QVERIFY(dialog);
    const auto *frob =
        entryFor(dialog->entries(), "Tools" + kSeparator + "Deeper" + kSeparator + "Frob");
    QVERIFY(frob);
    QCOMPARE(frob->keys,
             QKeySequence(QStringLiteral("Ctrl+Alt+F")).toString(QKeySequence::NativeText));
    QVERIFY(entryFor(dialog->entries(), "Window" + kSeparator + "Quux"));

    // Open still: triggering again reads the actions again.
    delete added;
    helpMenu()->shortcutsAction()->trigger();
    QCOMPARE(helpMenu()->shortcutsDialog(), dialog);
    QVERIFY(!entryFor(dialog->entries(), "Tools" + kSeparator + "Deeper" + kSeparator + "Frob"));
    delete tools;
    delete windowLevel;
    dialog->close();
}

void TestHelpMenu::aboutNamesVersionsAndRenderer()
{
    QCoreApplication::setApplicationVersion(QStringLiteral("9.8.7-test"));
    // The renderer as the view's own context names it, asked here.
    QString renderer, version;
    {
        const CurrentContext current(*viewport());
        QOpenGLFunctions *gl = viewport()->glContext().context()->functions();
        renderer =
            QString::fromLatin1(reinterpret_cast<const char *>(gl->glGetString(GL_RENDERER)));
        version = QString::fromLatin1(reinterpret_cast<const char *>(gl->glGetString(GL_VERSION)));
    }
    QVERIFY(!renderer.isEmpty());

    helpMenu()->aboutAction()->trigger();
    AboutDialog *about = helpMenu()->aboutDialog();
    QVERIFY(about);
    QVERIFY(about->isVisible());
    const QString text = about->text();
    for (const QString &expected : {QStringLiteral("9.8.7-test"), QString::fromLatin1(qVersion()),
                                    QStringLiteral(QT_VERSION_STR), renderer, version})
        QVERIFY2(text.contains(expected), qPrintable(expected + " not in:\n" + text));
    // OM_VERSION decoded by hand: 0xVMMmm (OpenMesh 9.0 is 0x90000).
    const QString openMesh = QStringLiteral("OpenMesh: %1.%2.%3")
                                 .arg(OM_VERSION >> 16)
                                 .arg((OM_VERSION >> 8) & 0xff)
                                 .arg(OM_VERSION & 0xff);
    QVERIFY2(text.contains(openMesh), qPrintable(text));
    QVERIFY(AboutDialog::openMeshVersion().section(u'.', 0, 0).toInt() >= 6);
    // The text is on screen, not only in the dialog object.
    const QLabel *shown = about->findChild<QLabel *>(QStringLiteral("versionReport"));
    QVERIFY(shown);
    QCOMPARE(shown->text(), text);
    saveArtifact(QStringLiteral("help-about.png"), about);
    about->close();
}

void TestHelpMenu::documentationOpensReadmeAndFollowsALink()
{
    helpMenu()->documentationAction()->trigger();
    DocumentationBrowser *docs = helpMenu()->documentationBrowser();
    QVERIFY2(docs,
             qPrintable(HelpMenu::missingDocumentationMessage(documentationSearchFolders(
                 StartupOptions::fromEnvironment().documentationFolder))));
    QVERIFY(QTest::qWaitForWindowExposed(docs));
    const QString readme = QDir::cleanPath(sourcePath(QStringLiteral("README.md")));
    QCOMPARE(docs->currentSource().toLocalFile(), readme);
    DocumentView *view = docs->view();
    QVERIFY(view->toPlainText().contains(QStringLiteral("New here?")));

    // Every doc is listed, README first, under its title.
    const int docCount = QDir(sourcePath(QStringLiteral("docs")))
                             .entryList({QStringLiteral("*.md")}, QDir::Files)
                             .size();
    const int germanCount = QDir(sourcePath(QStringLiteral("docs/de")))
                                .entryList({QStringLiteral("*.md")}, QDir::Files)
                                .size();
    QCOMPARE(docs->contents()->count(), 1 + docCount + germanCount);
    QCOMPARE(docs->contents()->item(0)->text(), QStringLiteral("PhongLab"));
    QCOMPARE(docs->contents()->currentRow(), 0);

    // Click README's link to the five-minute guide, as a reader would.
    const QPoint link = positionOfText(view, QStringLiteral("docs/first-five-minutes.md"));
    QVERIFY(link.x() >= 0);
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, link);
    const QString guide = QDir::cleanPath(sourcePath(QStringLiteral("docs/first-five-minutes.md")));
    QTRY_COMPARE(docs->currentSource().toLocalFile(), guide);
    QVERIFY(view->toPlainText().startsWith(QStringLiteral("PhongLab in five minutes")));
    QCOMPARE(docs->contents()->currentItem()->text(), QStringLiteral("PhongLab in five minutes"));
    QVERIFY(docs->windowTitle().contains(QStringLiteral("PhongLab in five minutes")));
    // Its images are found beside it, scaled to the reading width.
    const QImage image =
        view->loadResource(QTextDocument::ImageResource, QUrl(QStringLiteral("images/app.png")))
            .value<QImage>();
    QVERIFY(!image.isNull());
    QCOMPARE(qRound(image.width() / image.devicePixelRatio()), DocumentView::kMaxImageWidth);
    saveArtifact(QStringLiteral("help-documentation.png"), docs);

    // Back to README, and forward again.
    QVERIFY(view->isBackwardAvailable());
    view->backward();
    QCOMPARE(docs->currentSource().toLocalFile(), readme);
    QCOMPARE(docs->contents()->currentRow(), 0);
    view->forward();
    QCOMPARE(docs->currentSource().toLocalFile(), guide);

    // Choosing a doc in the list opens it.
    docs->contents()->setCurrentRow(docs->contents()->count() - 1);
    QCOMPARE(docs->currentSource().toLocalFile(), docs->documents().back());
    docs->close();
}

void TestHelpMenu::documentationFolderComesFromTheEnvironment()
{
    QTemporaryDir empty;
    qputenv("PHONGLAB_DOC_DIR", empty.path().toUtf8());
    const QString first = StartupOptions::fromEnvironment().documentationFolder;
    const QStringList searched = documentationSearchFolders(first);
    QCOMPARE(searched.front(), QDir::cleanPath(empty.path()));
    // An empty folder is passed over: the source tree's docs are next.
    QCOMPARE(documentationFolder(first), QDir::cleanPath(sourcePath({})));
    const QString message = HelpMenu::missingDocumentationMessage(searched);
    for (const QString &folder : searched)
        QVERIFY2(message.contains(QDir::toNativeSeparators(folder)), qPrintable(message));

    writeFile(empty.filePath(QStringLiteral("docs/only.md")), "# Only\n");
    QCOMPARE(documentationFolder(first), QDir::cleanPath(empty.path()));
    QCOMPARE(documentationFiles(documentationFolder(first)),
             QStringList{QDir::cleanPath(empty.filePath(QStringLiteral("docs/only.md")))});
    qunsetenv("PHONGLAB_DOC_DIR");
}

// In a German run F1 opens the German pages, and the contents
// list both languages' pages.
void TestHelpMenu::germanRunOpensTheGermanPages()
{
    QTemporaryDir folder;
    writeFile(folder.filePath(QStringLiteral("README.md")), "# Home\n");
    writeFile(folder.filePath(QStringLiteral("docs/guide.md")), "# Guide\n");
    writeFile(folder.filePath(QStringLiteral("docs/de/anleitung.md")), "# Anleitung\n");
    writeFile(folder.filePath(QStringLiteral("docs/de/README.md")), "# Start\n");
    const QString dir = QDir::cleanPath(folder.path());
    const QStringList german = documentationFiles(dir, QStringLiteral("de"));
    QCOMPARE(
        german,
        (QStringList{dir + QStringLiteral("/docs/de/README.md"),
                     dir + QStringLiteral("/docs/de/anleitung.md"),
                     dir + QStringLiteral("/README.md"), dir + QStringLiteral("/docs/guide.md")}));
    const QStringList english = documentationFiles(dir, QStringLiteral("en"));
    QCOMPARE(english.front(), dir + QStringLiteral("/README.md"));
    QVERIFY(english.contains(dir + QStringLiteral("/docs/de/README.md")));
}

// A link to a file the installation lacks says so and stays on the page;
// a link between docs works in both directions.
void TestHelpMenu::linkToAMissingFileSaysSo()
{
    QTemporaryDir folder;
    writeFile(folder.filePath(QStringLiteral("README.md")),
              "# Home\n\n[guide](docs/guide.md) and [gone](docs/gone.md)\n");
    writeFile(folder.filePath(QStringLiteral("docs/guide.md")),
              "# Guide\n\n[home](../README.md)\n");
    DocumentationBrowser docs(folder.path());
    DocumentView *view = docs.view();
    QVERIFY(view->toPlainText().startsWith(QStringLiteral("Home")));

    emit view->anchorClicked(QUrl(QStringLiteral("docs/gone.md")));
    QVERIFY(view->toPlainText().startsWith(QStringLiteral("Home")));
    QVERIFY2(docs.note().contains(QStringLiteral("docs/gone.md"))
                 && docs.note().contains(QStringLiteral("not part of")),
             qPrintable(docs.note()));

    emit view->anchorClicked(QUrl(QStringLiteral("docs/guide.md")));
    QVERIFY(view->toPlainText().startsWith(QStringLiteral("Guide")));
    QVERIFY(docs.note().isEmpty());
    emit view->anchorClicked(QUrl(QStringLiteral("../README.md")));
    QVERIFY(view->toPlainText().startsWith(QStringLiteral("Home")));
}

QTEST_MAIN(TestHelpMenu)
#include "tst_helpmenu.moc"
