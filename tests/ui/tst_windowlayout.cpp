// The first look: the window opens at a share of the screen with
// the code beside the view, 80 columns of it, its error list under it; no
// tab label is cut short; every dock is in the View menu; the view frames
// every object at that size and after a resize; View > Reset Layout brings
// the default back, and a layout saved under an older version gives way to
// the new default once.
#include "ResultChecks.h"
#include "ShaderDockParts.h"
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "core/scene/SceneJson.h"
#include "core/view/CameraFraming.h"
#include "mesh/loading/SceneMeshes.h"
#include "ui/check/CheckRunner.h"
#include "ui/check/LiveCheck.h"
#include "ui/check/PixelInspectorDock.h"
#include "ui/shaders/DiagnosticList.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/DefaultLayout.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QTabBar>
#include <QTest>
#include <algorithm>

using namespace phonglab;
using phonglab::test::sourcePath;

namespace {

QString defaultScenePathInSource()
{
    return sourcePath(QStringLiteral("assets/scenes/default.json"));
}

// Where every dock is: its area, whether it shows, whether it floats, and
// the docks it shares tabs with. Pixel sizes are left out: a layout laid out
// again may differ by a pixel where a splitter rounds.
QStringList describeDocks(const QMainWindow &window)
{
    QStringList lines;
    for (QDockWidget *dock : window.findChildren<QDockWidget *>()) {
        QStringList tabbed;
        for (QDockWidget *other : window.tabifiedDockWidgets(dock))
            tabbed << other->objectName();
        tabbed.sort();
        lines << QStringLiteral("%1 area %2 %3 %4 tabs [%5]")
                     .arg(dock->objectName())
                     .arg(int(window.dockWidgetArea(dock)))
                     .arg(dock->isVisible() ? QStringLiteral("shown") : QStringLiteral("hidden"))
                     .arg(dock->isFloating() ? QStringLiteral("floating")
                                             : QStringLiteral("docked"))
                     .arg(tabbed.join(u','));
    }
    lines.sort();
    return lines;
}

// The largest |x| or |y| in normalised device coordinates of any corner of
// any object's bounds: at most 1 when every object is in view.
double largestNdc(const Viewport &viewport)
{
    const Scene scene = viewport.currentScene();
    const double aspect = double(viewport.width()) / viewport.height();
    const glm::dmat4 viewProjection =
        scene.camera.projectionMatrix(aspect) * scene.camera.viewMatrix();
    double largest = 0.0;
    for (const glm::dvec3 &corner : objectBoundsCorners(scene, viewport.meshInfo())) {
        const glm::dvec4 clip = viewProjection * glm::dvec4(corner, 1.0);
        largest = std::max({largest, std::abs(clip.x / clip.w), std::abs(clip.y / clip.w)});
    }
    return largest;
}

// Whether the outermost rows and columns of `image` are all `background`.
bool edgesAreBackground(const QImage &image, const glm::dvec3 &background)
{
    const QColor expected =
        QColor::fromRgbF(float(background.r), float(background.g), float(background.b));
    const auto near = [&](int x, int y) {
        const QColor c = image.pixelColor(x, y);
        return std::abs(c.red() - expected.red()) <= 2
            && std::abs(c.green() - expected.green()) <= 2
            && std::abs(c.blue() - expected.blue()) <= 2;
    };
    for (int x = 0; x < image.width(); ++x)
        if (!near(x, 0) || !near(x, image.height() - 1))
            return false;
    for (int y = 0; y < image.height(); ++y)
        if (!near(0, y) || !near(image.width() - 1, y))
            return false;
    return true;
}

} // namespace

class TestWindowLayout : public QObject, private test::UiTestWindow
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void opensAtAShareOfTheScreen();
    void noTabLabelIsCutShort();
    void theCodeHas80ColumnsBesideTheView();
    void theCodeGetsRoomAtCommonScreenSizes_data();
    void theCodeGetsRoomAtCommonScreenSizes();
    void everyDockIsInTheViewMenu();
    void theViewFramesEveryObjectAtItsSizeAndAfterAResize();
    void resetLayoutBringsTheDefaultBack();
    void aWideWindowGivesTheSceneAColumn();
    void anOlderSavedLayoutGivesWayOnce();
    void theFirstLookChecksOut();
    void inspectGivesTheInspectorRoom();

private:
    // A window as a user gets it: not resized, shown at its default size.
    void openAtDefaultSize();
    QMenu *viewMenu() const;
    QAction *resetLayoutAction() const; // View > Reset Layout
    ShaderEditor *editor() const { return m_window->shaderDock()->editor(ShaderStage::Fragment); }
};

void TestWindowLayout::initTestCase()
{
    m_env.isolate();
    m_env.useFreshRecoveryDir("discard");
}

void TestWindowLayout::init()
{
    QSettings().clear();
    openAtDefaultSize();
}

void TestWindowLayout::cleanup()
{
    m_window.reset();
}

void TestWindowLayout::openAtDefaultSize()
{
    m_window = std::make_unique<MainWindow>();
    QVERIFY_OK(m_window->document()->openAndWait(defaultScenePathInSource()));
    test::showAndWaitForFrame(*m_window, m_window->size());
}

QMenu *TestWindowLayout::viewMenu() const
{
    for (QAction *action : m_window->menuBar()->actions())
        if (action->menu() && action->text().remove(u'&') == QStringLiteral("View"))
            return action->menu();
    return nullptr;
}

QAction *TestWindowLayout::resetLayoutAction() const
{
    QMenu *view = viewMenu();
    for (QAction *action : view ? view->actions() : QList<QAction *>())
        if (action->objectName() == QStringLiteral("resetLayout"))
            return action;
    return nullptr;
}

void TestWindowLayout::opensAtAShareOfTheScreen()
{
    const QRect available = m_window->screen()->availableGeometry();
    QCOMPARE(m_window->size(), defaultWindowGeometry(available).size());
    QVERIFY(available.contains(m_window->frameGeometry().center()));
    // The view keeps a good part of the window: not a strip between docks.
    const double widthShare = double(viewport()->width()) / m_window->width();
    const double heightShare = double(viewport()->height()) / m_window->height();
    QVERIFY2(widthShare >= 0.3 && widthShare <= 0.75, qPrintable(QString::number(widthShare)));
    QVERIFY2(heightShare >= 0.7, qPrintable(QString::number(heightShare)));
}

void TestWindowLayout::noTabLabelIsCutShort()
{
    int bars = 0;
    for (QTabBar *bar : m_window->findChildren<QTabBar *>()) {
        if (!bar->isVisible())
            continue;
        ++bars;
        QStringList labels;
        for (int i = 0; i < bar->count(); ++i)
            labels << bar->tabText(i);
        // A bar narrower than it asks for elides its labels to fit.
        QVERIFY2(bar->width() >= bar->sizeHint().width(),
                 qPrintable(QStringLiteral("%1: %2 < %3")
                                .arg(labels.join(u'|'))
                                .arg(bar->width())
                                .arg(bar->sizeHint().width())));
    }
    QVERIFY(bars >= 2); // the editor's stages and at least one group of docks
}

void TestWindowLayout::theCodeHas80ColumnsBesideTheView()
{
    // On a 1920x1080 screen (the view keeps half the width: on a smaller
    // one the code gets what is left of it).
    m_window->resize(defaultWindowGeometry(QRect(0, 0, 1920, 1040)).size());
    QTRY_COMPARE(m_window->width(), defaultWindowGeometry(QRect(0, 0, 1920, 1040)).width());
    m_window->resetLayout();
    ShaderEditor *code = editor();
    QTRY_VERIFY(code->visibleColumns() >= 80);
    QVERIFY(code->isVisible());
    QVERIFY2(code->visibleColumns() >= 80, qPrintable(QString::number(code->visibleColumns())));
    // Measured apart from visibleColumns(): the end of an 80-character line
    // lies inside the text area.
    code->setCode(QByteArray(80, 'm') + "\n" + code->code());
    code->setFirstVisibleLine(0);
    const long lineEnd = code->SendScintilla(QsciScintillaBase::SCI_GETLINEENDPOSITION, 0);
    const long x = code->SendScintilla(QsciScintillaBase::SCI_POINTXFROMPOSITION, 0, lineEnd);
    QVERIFY2(x <= code->viewport()->width(),
             qPrintable(QStringLiteral("line end at %1 px, text area %2 px, %3 columns")
                            .arg(x)
                            .arg(code->viewport()->width())
                            .arg(code->visibleColumns())));

    const QRect view(viewport()->mapTo(m_window.get(), QPoint()), viewport()->size());
    const QRect editorRect(code->mapTo(m_window.get(), QPoint()), code->size());
    QVERIFY(editorRect.left() >= view.right()); // beside the view, right of it
    // The error list shows under the code when there is something to say.
    DiagnosticList *errors = test::diagnosticList(m_window->shaderDock());
    QVERIFY(!errors->isVisible());
    errors->setDiagnostics(
        {ShaderDiagnostic{BuildStep::CompileFragment, ShaderDiagnostic::Severity::Error,
                          QStringLiteral("phong.frag"), 3, 1, QStringLiteral("syntax error")}});
    QTRY_VERIFY(errors->isVisible());
    QVERIFY(errors->mapTo(m_window.get(), QPoint()).y() >= editorRect.bottom()); // under it
    errors->setDiagnostics({});
    QVERIFY(!errors->isVisible());
}

// The code is what people come for: at the two commonest screen sizes the
// first window (a share of the screen, the default layout) shows at least
// 35 and 22 lines of it, with the view keeping at least half the width.
void TestWindowLayout::theCodeGetsRoomAtCommonScreenSizes_data()
{
    QTest::addColumn<QSize>("screen");
    QTest::addColumn<int>("lines");
    QTest::newRow("1920x1080") << QSize(1920, 1080) << 35;
    QTest::newRow("1366x768") << QSize(1366, 768) << 22;
}

void TestWindowLayout::theCodeGetsRoomAtCommonScreenSizes()
{
    QFETCH(QSize, screen);
    QFETCH(int, lines);
    // The screen's available area: less a taskbar's 40 pixels.
    const QRect available(QPoint(), screen - QSize(0, 40));
    m_window->resize(defaultWindowGeometry(available).size());
    QTRY_COMPARE(m_window->size(), defaultWindowGeometry(available).size());
    m_window->resetLayout();
    ShaderEditor *code = editor();
    QTRY_VERIFY(code->isVisible());
    QTest::qWait(50); // the docks settle after the layout's resizes
    const long shown = code->SendScintilla(QsciScintillaBase::SCI_LINESONSCREEN);
    qInfo("%dx%d screen: window %dx%d, %ld lines of code, view %d of %d px wide", screen.width(),
          screen.height(), m_window->width(), m_window->height(), shown, viewport()->width(),
          m_window->width());
    QVERIFY2(shown >= lines, qPrintable(QString::number(shown)));
    // The material under the code shows its rows, not 3 of them.
    QDockWidget *material = m_window->docks().material;
    material->raise();
    QTest::qWait(20);
    int fieldsInSight = 0;
    const QRect dockRect = material->rect();
    for (const QLineEdit *f : material->findChildren<QLineEdit *>())
        if (f->isVisible() && dockRect.contains(QRect(f->mapTo(material, QPoint()), f->size())))
            ++fieldsInSight;
    qInfo("material: %d fields in sight, dock %d px high", fieldsInSight, material->height());
    QVERIFY2(fieldsInSight >= 6, qPrintable(QString::number(fieldsInSight))); // ka and kd at least
    // The tab the user chooses shows its contents (3 rows of the
    // material were all a laptop's first window showed, the uniforms 2):
    // every field in its scroll area's sight, none scrolled away.
    const int heightAtFirst = material->height();
    m_window->docks().uniforms->raise(); // as a click on its tab does
    material->raise();
    QTest::qWait(50);
    auto *scroll = qobject_cast<QScrollArea *>(material->widget());
    QVERIFY(scroll);
    fieldsInSight = 0;
    for (const QLineEdit *f : material->findChildren<QLineEdit *>())
        if (f->isVisible()
            && scroll->viewport()->rect().contains(
                QRect(f->mapTo(scroll->viewport(), QPoint()), f->size())))
            ++fieldsInSight;
    qInfo("material after its tab was chosen: %d fields in sight, %d px high (first %d)",
          fieldsInSight, material->height(), heightAtFirst);
    QVERIFY2(fieldsInSight >= 10, qPrintable(QString::number(fieldsInSight))); // ka, kd, ks, n
    QVERIFY2(viewport()->width() * 2 >= m_window->width(),
             qPrintable(
                 QStringLiteral("view %1 of %2").arg(viewport()->width()).arg(m_window->width())));
    if (screen.width() >= 1600)
        QVERIFY(code->visibleColumns() >= 80);
    // No error: the error list takes no room.
    QVERIFY(!test::diagnosticList(m_window->shaderDock())->isVisible());
    // The material's fields, in a scroll area now, are there to edit.
    const QList<QLineEdit *> fields = m_window->docks().material->findChildren<QLineEdit *>();
    QVERIFY(!fields.isEmpty());
    QTRY_VERIFY(
        std::all_of(fields.begin(), fields.end(), [](QLineEdit *f) { return f->isEnabled(); }));
}

void TestWindowLayout::everyDockIsInTheViewMenu()
{
    QMenu *view = viewMenu();
    QVERIFY(view);
    const QList<QDockWidget *> docks = m_window->findChildren<QDockWidget *>();
    QCOMPARE(docks.size(), 9);
    for (QDockWidget *dock : docks)
        QVERIFY2(view->actions().contains(dock->toggleViewAction()),
                 qPrintable(dock->objectName()));
    // Measuring and the inspector come on demand.
    QVERIFY(!m_window->docks().performance->isVisible());
    QVERIFY(!m_window->docks().inspector->isVisible());
    QAction *reset = resetLayoutAction();
    QVERIFY(reset);
}

void TestWindowLayout::theViewFramesEveryObjectAtItsSizeAndAfterAResize()
{
    const Scene loaded = *loadSceneFile(defaultScenePathInSource()).scene;
    viewport()->drawing().setShowLightMarkers(
        false); // the lights need not be in view, the objects must
    QVERIFY2(largestNdc(*viewport()) <= 1.0, qPrintable(QString::number(largestNdc(*viewport()))));
    QVERIFY(edgesAreBackground(frame(), loaded.background));

    for (const QSize size : {QSize(m_window->width() * 2 / 3, m_window->height()),
                             QSize(m_window->width(), m_window->height() / 2)}) {
        m_window->resize(size);
        QTRY_VERIFY(largestNdc(*viewport()) <= 1.0);
        // The view's native window follows the widget a moment later.
        QTRY_COMPARE(viewport()->frames().window()->size(), viewport()->size());
        QVERIFY(edgesAreBackground(frame(), loaded.background));
    }
    // The camera is the scene's, only moved back: the framing keeps its line of sight.
    const Camera shown = viewport()->camera();
    QCOMPARE(shown.target, loaded.camera.target);
    QVERIFY(glm::length(glm::normalize(shown.eye - shown.target)
                        - glm::normalize(loaded.camera.eye - loaded.camera.target))
            < 1e-12);
    QCOMPARE(viewport()->cameraToSave(), loaded.camera); // Save writes the scene's own

    // Once the user moves the camera, a resize leaves it where they put it.
    const QPoint centre = viewport()->rect().center();
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, centre);
    QTest::mouseMove(viewport(), centre + QPoint(30, 10));
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, centre + QPoint(30, 10));
    const Camera moved = viewport()->camera();
    const int framesBefore = viewport()->frames().frameStats().rendered;
    m_window->resize(m_window->width() * 2 / 3, m_window->height());
    // A frame at the new size: the resize has been dealt with in full.
    QTRY_VERIFY(viewport()->width() < m_window->width()
                && viewport()->frames().frameStats().rendered > framesBefore);
    QCOMPARE(viewport()->camera(), moved);
}

void TestWindowLayout::resetLayoutBringsTheDefaultBack()
{
    const QStringList defaults = describeDocks(*m_window);
    const WindowDocks docks = m_window->docks();
    // A user's rearrangement: the code to the left, the material floating,
    // the scene closed, measuring opened.
    m_window->addDockWidget(Qt::LeftDockWidgetArea, docks.shaders);
    docks.material->setFloating(true);
    docks.scene->close();
    docks.performance->show();
    QTRY_VERIFY(describeDocks(*m_window) != defaults);

    QAction *reset = resetLayoutAction();
    QVERIFY(reset);
    reset->trigger();
    QTRY_COMPARE(describeDocks(*m_window), defaults);
    // The code back right of the view, which keeps half the width.
    QTRY_VERIFY(viewport()->width() * 2 >= m_window->width()
                && editor()->mapTo(m_window.get(), QPoint()).x() > viewport()->width());
}

void TestWindowLayout::aWideWindowGivesTheSceneAColumn()
{
    // Wide enough for a scene column and the code beside a view of half the
    // window (a 2560-pixel screen's).
    const int editorWidth = m_window->shaderDock()->sizeHint().width();
    m_window->resize(2 * (kSceneColumnWidth + editorWidth) + 100, 800);
    m_window->resetLayout();
    const WindowDocks docks = m_window->docks();
    QTRY_COMPARE(m_window->dockWidgetArea(docks.scene), Qt::LeftDockWidgetArea);
    QCOMPARE(m_window->dockWidgetArea(docks.shaders), Qt::RightDockWidgetArea);
    QCOMPARE(m_window->dockWidgetArea(docks.material), Qt::RightDockWidgetArea);
    QVERIFY(m_window->tabifiedDockWidgets(docks.scene).contains(docks.lights));
    QVERIFY(m_window->tabifiedDockWidgets(docks.material).contains(docks.uniforms));
    QTRY_VERIFY(viewport()->width() * 2 >= m_window->width());
    QTRY_VERIFY(editor()->visibleColumns() >= 80);
    for (QTabBar *bar : m_window->findChildren<QTabBar *>())
        if (bar->isVisible())
            QVERIFY(bar->width() >= bar->sizeHint().width());
}

void TestWindowLayout::anOlderSavedLayoutGivesWayOnce()
{
    const QStringList defaults = describeDocks(*m_window);
    // A layout saved by an older PhongLab (before the code got its room):
    // the code closed, under version 2.
    m_window->docks().shaders->close();
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), m_window->saveGeometry());
    settings.setValue(QStringLiteral("window/state"), m_window->saveState(2));
    settings.sync();

    openAtDefaultSize();
    QVERIFY(!m_window->restoreWindowSettings()); // the old state is not taken
    QTRY_COMPARE(describeDocks(*m_window), defaults);
    m_window->docks().lights->raise();
    m_window->saveWindowSettings(); // what closing the window does

    // The next start takes the layout saved under the new version.
    openAtDefaultSize();
    QVERIFY(m_window->restoreWindowSettings());
    QTRY_COMPARE(describeDocks(*m_window), defaults);
}

// The shipped shaders on the default scene at the default size: the check
// against the exact image says so.
void TestWindowLayout::theFirstLookChecksOut()
{
    LiveCheck *check = m_window->liveCheck();
    QTRY_VERIFY_WITH_TIMEOUT(check->lastResult().has_value() && !check->isChecking(), 60000);
    const CheckReport &report = check->lastResult()->report();
    QVERIFY2(report.passed(), qPrintable(check->statusLabel()->verdict()));
}

// At a laptop's size the inspector showed 5 lines of its terms.
// Brought forward by Inspect it is in front, and the tabs grow to its text
// (up to half the column), the code giving the room.
void TestWindowLayout::inspectGivesTheInspectorRoom()
{
    const QRect available(QPoint(), QSize(1366, 768) - QSize(0, 40));
    m_window->resize(defaultWindowGeometry(available).size());
    QTRY_COMPARE(m_window->size(), defaultWindowGeometry(available).size());
    m_window->resetLayout();
    // The check's ellipsoid fills the view's centre (the default scene's is
    // background between the tree and the cloud).
    QVERIFY_OK(
        m_window->document()->openAndWait(sourcePath(QStringLiteral("assets/scenes/check.json"))));
    LiveCheck *check = m_window->liveCheck();
    QTRY_VERIFY_WITH_TIMEOUT(check->lastResult().has_value() && !check->isChecking()
                                 && check->lastResult()->scene.objects.size() == 2,
                             60000);
    QDockWidget *inspector = m_window->docks().inspector;
    const int before = inspector->isVisible() ? inspector->height() : 0;
    check->inspect(viewport()->rect().center());
    QTRY_VERIFY_WITH_TIMEOUT(check->inspector()->text().contains(QStringLiteral("f_att")), 60000);
    QVERIFY(inspector->isVisible() && !inspector->visibleRegion().isEmpty());
    const int column = m_window->shaderDock()->height() + inspector->height();
    QTRY_VERIFY2(inspector->height() >= int(column * 0.45),
                 qPrintable(QStringLiteral("inspector %1 px of a %2 px column (before %3)")
                                .arg(inspector->height())
                                .arg(column)
                                .arg(before)));
    auto *terms = inspector->findChild<QPlainTextEdit *>();
    QVERIFY(terms);
    const int linesShown = terms->viewport()->height() / terms->fontMetrics().lineSpacing();
    QVERIFY2(linesShown >= 12, qPrintable(QString::number(linesShown)));
}

QTEST_MAIN(TestWindowLayout)
#include "tst_windowlayout.moc"
