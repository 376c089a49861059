// File → Run the Page in the real window (ui/check/PageRunDialog): the
// project's page runs in headless Chromium in the background, then the
// browser's frame, PhongLab's drawing of it and their difference show side
// by side with what `check --page` finds; a run can be cancelled, and a
// window closed on a run waits for nothing but the browser's end.
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "core/page/BrowserPipe.h"
#include "ui/check/PageRunDialog.h"
#include "ui/window/MainWindow.h"

#include <QAction>
#include <QElapsedTimer>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTextBrowser>

using namespace phonglab;
using namespace phonglab::test;

class TestPageRunDialog : public QObject, private UiTestWindow
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase() { m_window.reset(); }
    void theFileMenuRunsThePage();
    void aRunShowsTheFramesAndTheFindings();
    void aRunCanBeCancelled();

private:
    PageRequest request(const QString &project) const;
};

void TestPageRunDialog::initTestCase()
{
    m_env.isolate();
    if (BrowserPipe::executable().isEmpty())
        QSKIP("chromium is not installed (scripts/setup.sh installs it)");
    openWindow(sourcePath(QStringLiteral("assets/scenes/sphere.json")), {800, 600});
    QVERIFY(!QTest::currentTestFailed());
}

PageRequest TestPageRunDialog::request(const QString &project) const
{
    PageRequest r;
    r.run.folders.project = testDataPath(QStringLiteral("pages/") + project);
    r.run.folders.libraries = {testDataPath(QStringLiteral("pages")),
                               sourcePath(QStringLiteral("assets/meshes"))};
    return r;
}

void TestPageRunDialog::theFileMenuRunsThePage()
{
    auto *action = m_window->findChild<QAction *>(QStringLiteral("runThePage"));
    QVERIFY(action);
    QVERIFY(action->isEnabled());
}

void TestPageRunDialog::aRunShowsTheFramesAndTheFindings()
{
    PageRunDialog dialog(request(QStringLiteral("angel")), m_window.get());
    dialog.show();
    QSignalSpy finished(&dialog, &PageRunDialog::runFinished);
    QVERIFY(finished.wait(60000));
    QVERIFY(dialog.finished());
    for (const char *name : {"pageBrowserFrame", "pageDrawnFrame", "pageDifferenceFrame"}) {
        auto *label = dialog.findChild<QLabel *>(QLatin1String(name));
        QVERIFY2(label && !label->pixmap().isNull(), name);
    }
    const QString text =
        dialog.findChild<QTextBrowser *>(QStringLiteral("pageFindings"))->toPlainText();
    QVERIFY2(text.contains(
                 QLatin1String("fidelity: PhongLab draws the page's frame as the browser did")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("own scene: ✓")), qPrintable(text));
    QCOMPARE(dialog.findChild<QPushButton *>(QStringLiteral("pageRunButton"))->text(),
             QStringLiteral("Close"));
}

// A page whose script never ends: Cancel stops the browser at its next
// wait, long before the time limit.
void TestPageRunDialog::aRunCanBeCancelled()
{
    PageRequest endless = request(QStringLiteral("endless-loop"));
    endless.run.timeLimitMs = 60000;
    PageRunDialog dialog(endless, m_window.get());
    dialog.show();
    QSignalSpy finished(&dialog, &PageRunDialog::runFinished);
    QVERIFY(!dialog.finished()); // the browser is starting, or already in the page's loop
    QElapsedTimer clock;
    clock.start();
    QTest::mouseClick(dialog.findChild<QPushButton *>(QStringLiteral("pageRunButton")),
                      Qt::LeftButton);
    QVERIFY(finished.wait(10000));
    qInfo("cancelled after %lld ms", clock.elapsed());
    QVERIFY(clock.elapsed() < 5000);
    QCOMPARE(dialog.findChild<QLabel *>(QStringLiteral("pageRunStatus"))->text(),
             QStringLiteral("Cancelled."));
}

QTEST_MAIN(TestPageRunDialog)
#include "tst_pagerundialog.moc"
