// File → Examples: every shipped scene has a thumbnail (on disk and in the
// binary), the menu lists every scene with its thumbnail, and choosing one
// opens it the way File → Open does.
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "core/scene/ResourcePaths.h"
#include "core/scene/SceneJson.h"
#include "ui/scene/SceneLoadJob.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/ExamplesMenu.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"

#include "core/scene/ResourcePaths.h"
#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QMenu>
#include <QMenuBar>

#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

constexpr int kLoadTimeoutMs = 60000;
const QSize kThumbnailSize(128, 96); // scripts/make-thumbnails.sh

QStringList shippedSceneNames()
{
    QStringList names;
    for (const QString &file : QDir(sourcePath(QStringLiteral("assets/scenes")))
                                   .entryList({QStringLiteral("*.json")}, QDir::Files))
        names << QFileInfo(file).completeBaseName();
    return names;
}

QMenu *subMenu(QMenu *menu, const QString &text)
{
    for (QAction *action : menu->actions())
        if (action->menu() && action->text() == text)
            return action->menu();
    return nullptr;
}

} // namespace

class TestExamplesMenu : public QObject, private UiTestWindow
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase() { m_window.reset(); }

    void everySceneHasAThumbnail();
    void menuListsEverySceneWithItsThumbnail();
    void choosingAnExampleOpensIt_data();
    void choosingAnExampleOpensIt();

private:
    QMenu *examplesMenu() const;
};

void TestExamplesMenu::initTestCase()
{
    m_env.isolate();
    QVERIFY(shippedSceneNames().size() >= 5);
    openWindow(testDataPath(QStringLiteral("scenes/gl_cube.json")), {640, 480});
}

QMenu *TestExamplesMenu::examplesMenu() const
{
    const QList<QAction *> menus = m_window->menuBar()->actions();
    const auto file = std::find_if(menus.begin(), menus.end(), [](const QAction *a) {
        return a->text() == QStringLiteral("&File");
    });
    return file == menus.end() ? nullptr : subMenu((*file)->menu(), QStringLiteral("E&xamples"));
}

void TestExamplesMenu::everySceneHasAThumbnail()
{
    for (const QString &name : shippedSceneNames()) {
        const QString relative = QStringLiteral("scenes/thumbnails/%1.png").arg(name);
        // In the source tree (installed with the scenes) and in the binary.
        for (const QString &path : {sourcePath(QStringLiteral("assets/") + relative),
                                    QStringLiteral(":/assets/") + relative}) {
            const QImage thumbnail(path);
            QVERIFY2(!thumbnail.isNull(), qPrintable(path + " is missing"));
            QCOMPARE(thumbnail.size(), kThumbnailSize);
        }
        // A picture of a scene, not a blank: more than one colour.
        const QImage thumbnail(sourcePath(QStringLiteral("assets/") + relative));
        QSet<QRgb> colours;
        for (int y = 0; y < thumbnail.height(); y += 4)
            for (int x = 0; x < thumbnail.width(); x += 4)
                colours.insert(thumbnail.pixel(x, y));
        QVERIFY2(colours.size() > 10, qPrintable(name));
    }
}

void TestExamplesMenu::menuListsEverySceneWithItsThumbnail()
{
    QMenu *menu = examplesMenu();
    QVERIFY(menu);
    QStringList listed, titles;
    for (const QAction *action : menu->actions()) {
        listed << QFileInfo(action->data().toString()).completeBaseName();
        titles << action->text();
        QVERIFY2(!action->icon().isNull(), qPrintable(action->text()));
        QVERIFY(!action->text().isEmpty());
    }
    QCOMPARE(listed.front(), QStringLiteral("default")); // where a new user starts
    listed.sort();
    QStringList shipped = shippedSceneNames();
    shipped.sort();
    QCOMPARE(listed, shipped);
    titles.removeDuplicates();
    QCOMPARE(titles.size(), shipped.size());
    const QString artifacts = qEnvironmentVariable("PHONGLAB_TEST_ARTIFACTS");
    if (!artifacts.isEmpty() && QDir().mkpath(artifacts)) { // for a person to look at
        menu->popup(m_window->mapToGlobal(QPoint(20, 20)));
        QVERIFY(QTest::qWaitForWindowExposed(menu));
        menu->grab().save(QDir(artifacts).filePath(QStringLiteral("file-examples.png")));
        menu->hide();
    }
    QCOMPARE(ExamplesMenu::title(QStringLiteral("grazing.json")),
             QStringLiteral("Grazing Light on a Box"));
    QCOMPARE(ExamplesMenu::title(QStringLiteral("/x/my-new_scene.json")),
             QStringLiteral("My new scene"));
}

void TestExamplesMenu::choosingAnExampleOpensIt_data()
{
    QTest::addColumn<QString>("name");
    for (const QString &name : shippedSceneNames())
        QTest::newRow(qPrintable(name)) << name;
}

void TestExamplesMenu::choosingAnExampleOpensIt()
{
    QFETCH(QString, name);
    // From another scene, so the change is seen.
    QVERIFY(m_window->document()
                ->openAndWait(testDataPath(QStringLiteral("scenes/gl_cube.json")))
                .ok());
    QMenu *menu = examplesMenu();
    QVERIFY(menu);
    QAction *chosen = nullptr;
    for (QAction *action : menu->actions())
        if (QFileInfo(action->data().toString()).completeBaseName() == name)
            chosen = action;
    QVERIFY(chosen);
    chosen->trigger();

    const QString file = name + QStringLiteral(".json");
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(m_window->document()->path()).fileName() == file
                                 && !m_window->document()->loadJob()->isRunning(),
                             kLoadTimeoutMs);
    QCOMPARE(QFileInfo(m_window->document()->path()).canonicalFilePath(),
             QFileInfo(sourcePath(QStringLiteral("assets/scenes/") + file)).canonicalFilePath());
    QVERIFY2(m_window->windowTitle().startsWith(file), qPrintable(m_window->windowTitle()));
    // The scene shown is the file's.
    const SceneLoadResult expected = loadSceneFile(m_window->document()->path());
    QVERIFY(expected.ok());
    const Scene shown = viewport()->currentScene();
    QCOMPARE(shown.objects.size(), expected.scene->objects.size());
    for (size_t i = 0; i < shown.objects.size(); ++i)
        QCOMPARE(shown.objects[i].mesh, expected.scene->objects[i].mesh);
    // Save does not write over an example (File → Save asks where instead).
    QVERIFY(isShippedScene(m_window->document()->path()));
    QVERIFY(!isShippedScene(testDataPath(QStringLiteral("scenes/gl_cube.json"))));
}

QTEST_MAIN(TestExamplesMenu)
#include "tst_examplesmenu.moc"
