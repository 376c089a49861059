// The Performance dock on the default scene (tree and cloud): Fit to budget
// measures the current view with `phonglab bench` in a child process, picks
// a model whose measured error is within the default budget (max 2/255 away
// from silhouettes), shows it, draws fewer or equal triangles, charts the
// measurement and reports the savings; Full detail goes back.
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "core/scene/Scene.h"
#include "ui/performance/PerformanceDock.h"
#include "ui/viewport/DetailLevelLabel.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/MainWindow.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QLabel>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>
#include <memory>

using namespace phonglab;
using phonglab::test::sourcePath;

namespace {

constexpr int kMeasureTimeoutMs = 240000; // 2 loaded cores; about 20 s when idle

} // namespace

class TestPerformanceDock : public QObject, private test::UiTestWindow
{
    Q_OBJECT

private slots:
    void initTestCase();
    void fitsDefaultSceneToBudget();
    void nothingFitsLeavesSceneAlone();
    void autoDetailToggleShowsTheLevels();
    void frameReadoutOnlyWhileSeen();

private:
    void openWindow();
    PerformanceDock *dock() const { return m_window->performanceDock(); }
};

void TestPerformanceDock::initTestCase()
{
    m_env.isolate();
    m_env.useFreshRecoveryDir("discard"); // one for the whole test case
    QVERIFY2(!qEnvironmentVariableIsEmpty("PHONGLAB_EXE"),
             "the dock runs the phonglab binary: set PHONGLAB_EXE");
}

void TestPerformanceDock::openWindow()
{
    UiTestWindow::openWindow(sourcePath(QStringLiteral("assets/scenes/default.json")), {1000, 700});
    if (QTest::currentTestFailed())
        return;
    dock()->show(); // hidden until asked for, as View > Performance Dock does
    dock()->raise();
}

void TestPerformanceDock::fitsDefaultSceneToBudget()
{
    openWindow();
    QCOMPARE(dock()->budget().kind, ErrorBudget::Kind::MaxError);
    QCOMPARE(dock()->budget().maxError, 2);
    qint64 trianglesBefore = 0;
    connect(
        viewport(), &Viewport::frameRendered, this,
        [&trianglesBefore](double, qint64 triangles) { trianglesBefore = triangles; },
        Qt::SingleShotConnection);
    viewport()->frames().requestFrame();
    QTRY_VERIFY(trianglesBefore > 0);

    QSignalSpy applied(dock(), &PerformanceDock::fitApplied);
    dock()->fitToBudget();
    QVERIFY(dock()->isMeasuring());
    QTRY_VERIFY_WITH_TIMEOUT(!dock()->isMeasuring(), kMeasureTimeoutMs);
    QVERIFY2(!dock()->rows().empty(), qPrintable(dock()->reportText()));
    const BudgetFit fit = dock()->lastFit();
    QVERIFY2(fit.chosen >= 0, qPrintable(dock()->reportText()));
    QCOMPARE(applied.count(), 1);
    const BenchRow chosen = dock()->rows()[std::size_t(fit.chosen)];
    qInfo("fit: %s", qPrintable(fit.summary));
    // The choice was measured within the budget, with the scene's own lights.
    QVERIFY(chosen.sceneLights);
    QVERIFY2(chosen.maxError <= 2, qPrintable(fit.summary));
    for (const BenchRow &row : dock()->rows())
        QVERIFY(row.sceneLights && row.scene == dock()->rows().front().scene);

    // The window now shows that model.
    QTRY_VERIFY_WITH_TIMEOUT(viewport()->currentScene().shading == *shadingFromName(chosen.method),
                             60000);
    for (const SceneObject &object : viewport()->currentScene().objects)
        QTRY_COMPARE(object.detail, chosen.detail);
    qint64 trianglesAfter = 0;
    connect(viewport(), &Viewport::frameRendered, this,
            [&trianglesAfter](double, qint64 triangles) { trianglesAfter = triangles; });
    viewport()->frames().requestFrame();
    QTRY_VERIFY(trianglesAfter > 0);
    QVERIFY(trianglesAfter <= trianglesBefore);
    QCOMPARE(trianglesAfter, chosen.triangles);
    QVERIFY2(dock()->reportText().contains(QStringLiteral("Saved")),
             qPrintable(dock()->reportText()));

    // The chart of this measurement: a series per method plus the front.
    auto *view = dock()->findChild<QChartView *>();
    QVERIFY(view && view->chart());
    QVERIFY(view->chart()->series().size() >= 4);

    dock()->restoreFullDetail();
    QTRY_VERIFY_WITH_TIMEOUT(viewport()->currentScene().objects.front().detail == 1.0, 60000);
    QTRY_COMPARE(viewport()->currentScene().shading, ShadingMethod::Phong);
}

void TestPerformanceDock::nothingFitsLeavesSceneAlone()
{
    openWindow();
    // Closer in, where even the full-detail program differs from the exact
    // image by a step somewhere (seen from further back it can match it).
    const QPointF centre = QPointF(viewport()->rect().center());
    QWheelEvent wheel(centre, viewport()->mapToGlobal(centre), QPoint(), QPoint(0, 120 * 3),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &wheel);
    ErrorBudget impossible;
    impossible.kind = ErrorBudget::Kind::Psnr;
    impossible.minPsnr = 99.0;
    dock()->setBudget(impossible);
    const Scene before = viewport()->currentScene();
    QSignalSpy applied(dock(), &PerformanceDock::fitApplied);
    dock()->fitToBudget();
    QTRY_VERIFY_WITH_TIMEOUT(!dock()->isMeasuring(), kMeasureTimeoutMs);
    QVERIFY(!dock()->rows().empty());
    QCOMPARE(dock()->lastFit().chosen, -1);
    QCOMPARE(applied.count(), 0);
    QVERIFY2(!dock()->reportText().isEmpty(), "says why nothing was applied");
    QCOMPARE(viewport()->currentScene().shading, before.shading);
    QCOMPARE(viewport()->currentScene().objects.front().detail, 1.0);
}

// The toggle puts every object at "detail": "auto" (levels built by the
// load, in the background), the viewport says which level each object
// draws, and the toggle follows the scene; off goes back to full detail.
void TestPerformanceDock::autoDetailToggleShowsTheLevels()
{
    openWindow();
    auto *toggle = dock()->findChild<QCheckBox *>(QStringLiteral("autoDetail"));
    QVERIFY(toggle);
    QVERIFY(!toggle->isChecked());
    auto *label = viewport()->findChild<DetailLevelLabel *>(QStringLiteral("detailLevels"));
    QVERIFY(label);
    QVERIFY(!label->isVisible());

    toggle->click();
    QTRY_VERIFY_WITH_TIMEOUT(viewport()->currentScene().objects.front().autoDetail, 60000);
    for (const SceneObject &object : viewport()->currentScene().objects)
        QVERIFY(object.autoDetail);
    viewport()->frames().requestFrame();
    QTRY_VERIFY(label->isVisible());
    QVERIFY2(label->text().contains(QStringLiteral("tree.obj: level ")), qPrintable(label->text()));
    QVERIFY2(label->text().contains(QStringLiteral("cloud.obj: level ")),
             qPrintable(label->text()));
    QVERIFY(viewport()->drawing().objectDraws().front().levels > 1);
    QVERIFY(toggle->isChecked());

    toggle->click();
    QTRY_VERIFY_WITH_TIMEOUT(!viewport()->currentScene().objects.front().autoDetail, 60000);
    viewport()->frames().requestFrame();
    QTRY_VERIFY(!label->isVisible());
    QCOMPARE(viewport()->drawing().objectDraws().front().levels, 1);
}

// The dock's frame readout is written only while it can be seen (a label
// written on every frame costs a relayout and a repaint of the window), and
// shows the figures at once when the dock comes into sight.
void TestPerformanceDock::frameReadoutOnlyWhileSeen()
{
    openWindow();
    QLabel *readout = nullptr;
    for (QLabel *label : dock()->findChildren<QLabel *>())
        if (label->text().startsWith(QStringLiteral("Frame:")))
            readout = label;
    QVERIFY(readout);
    QTRY_VERIFY(readout->text().contains(QStringLiteral("triangles")));
    qint64 nowMs = 1'000'000; // the pace's clock, moved on by hand
    dock()->setReadoutClock([&nowMs] { return nowMs; });

    // Afloat: hiding and showing it leaves the view's size, and so its
    // frames, alone.
    dock()->setFloating(true);
    dock()->hide();
    QTRY_VERIFY(!readout->isVisible());
    readout->setText(QStringLiteral("Frame: stale"));
    nowMs += ReadoutPace::kIntervalMs; // a readout in sight would be due now
    for (int i = 0; i < 5; ++i) {
        const int frames = viewport()->frames().frameStats().rendered;
        viewport()->frames().requestFrame();
        QTRY_VERIFY(viewport()->frames().frameStats().rendered > frames);
    }
    QCOMPARE(readout->text(), QStringLiteral("Frame: stale"));

    dock()->show(); // no frame asked for here: the dock asks for one
    QTRY_VERIFY(readout->isVisible());
    QTRY_VERIFY2(readout->text().contains(QStringLiteral("triangles")),
                 qPrintable(readout->text()));
}

QTEST_MAIN(TestPerformanceDock)
#include "tst_performancedock.moc"
