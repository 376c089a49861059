// The Performance dock on the default scene (tree and cloud): Fit to budget
// measures the current view with `phonglab bench` in a child process, picks
// a model whose measured error is within the default budget (max 2/255 away
// from silhouettes), shows it, draws fewer or equal triangles, charts the
// measurement and reports the savings; Full detail goes back.
#include "core/Scene.h"
#include "render/GlFormat.h"
#include "ui/MainWindow.h"
#include "ui/PerformanceDock.h"
#include "ui/Viewport.h"

#include <QChart>
#include <QChartView>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <memory>

using namespace phonglab;

namespace {

constexpr int kMeasureTimeoutMs = 240000; // 2 loaded cores; about 20 s when idle

QString sourcePath(const QString &relative)
{
    return QStringLiteral(PHONGLAB_SOURCE_DIR "/") + relative;
}

} // namespace

class TestPerformanceDock : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void fitsDefaultSceneToBudget();
    void nothingFitsLeavesSceneAlone();

private:
    void openWindow();
    PerformanceDock *dock() const { return m_window->performanceDock(); }
    Viewport *viewport() const { return m_window->viewport(); }

    QTemporaryDir m_cacheDir;
    QTemporaryDir m_recoveryDir;
    std::unique_ptr<MainWindow> m_window;
};

void TestPerformanceDock::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
    if (qEnvironmentVariableIsEmpty("PHONGLAB_CACHE_DIR"))
        qputenv("PHONGLAB_CACHE_DIR", m_cacheDir.path().toUtf8());
    qputenv("PHONGLAB_RECOVERY_DIR", m_recoveryDir.path().toUtf8());
    qputenv("PHONGLAB_RECOVERY_ANSWER", "discard");
    QVERIFY2(!qEnvironmentVariableIsEmpty("PHONGLAB_EXE"), "the dock runs the phonglab binary: set PHONGLAB_EXE");
}

void TestPerformanceDock::openWindow()
{
    m_window = std::make_unique<MainWindow>();
    QString error;
    QVERIFY2(m_window->openScene(sourcePath(QStringLiteral("assets/scenes/default.json")), &error), qPrintable(error));
    m_window->resize(1000, 700);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QTRY_VERIFY(viewport()->framesRendered() > 0);
    dock()->raise();
}

void TestPerformanceDock::fitsDefaultSceneToBudget()
{
    openWindow();
    QCOMPARE(dock()->budget().kind, ErrorBudget::Kind::MaxError);
    QCOMPARE(dock()->budget().maxError, 2);
    qint64 trianglesBefore = 0;
    connect(viewport(), &Viewport::frameRendered, this,
            [&trianglesBefore](double, qint64 triangles) { trianglesBefore = triangles; }, Qt::SingleShotConnection);
    viewport()->update();
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
    QTRY_VERIFY_WITH_TIMEOUT(viewport()->currentScene().shading == *shadingFromName(chosen.method), 60000);
    for (const SceneObject &object : viewport()->currentScene().objects)
        QTRY_COMPARE(object.detail, chosen.detail);
    qint64 trianglesAfter = 0;
    connect(viewport(), &Viewport::frameRendered, this,
            [&trianglesAfter](double, qint64 triangles) { trianglesAfter = triangles; });
    viewport()->update();
    QTRY_VERIFY(trianglesAfter > 0);
    QVERIFY(trianglesAfter <= trianglesBefore);
    QCOMPARE(trianglesAfter, chosen.triangles);
    QVERIFY2(dock()->reportText().contains(QStringLiteral("Saved")), qPrintable(dock()->reportText()));

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

QTEST_MAIN(TestPerformanceDock)
#include "tst_performancedock.moc"
