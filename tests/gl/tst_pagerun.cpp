// A student's page run in headless Chromium (core/page/PageRun) and what
// its capture holds (core/page/PageCapture): the test projects of
// tests/data/pages, each made to show one thing a real course page does.
#include "TestPaths.h"
#include "core/page/BrowserPipe.h"
#include "core/page/PageCapture.h"
#include "core/page/PageRun.h"

#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

PageRunOptions pageOptions(const QString &project)
{
    PageRunOptions options;
    options.folders.project = testDataPath(QStringLiteral("pages/") + project);
    options.folders.libraries = {testDataPath(QStringLiteral("pages")),
                                 testDataPath(QStringLiteral("meshes/blender"))};
    return options;
}

} // namespace

class TestPageRun : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void angelPageIsCaptured();
};

void TestPageRun::initTestCase()
{
    if (BrowserPipe::executable().isEmpty())
        QSKIP("chromium is not installed (scripts/setup.sh installs it)");
}

void TestPageRun::angelPageIsCaptured()
{
    const Result<PageRunOutput> run = runPage(pageOptions(QStringLiteral("angel")));
    QVERIFY2(run.ok(), qPrintable(run.error()));
    const Result<PageCapture> capture = readPageCapture(run->capture);
    QVERIFY2(capture.ok(), qPrintable(capture.error()));
    qInfo("%lld ms; frame %d, %zu ops, served %s; refused %s; errors %s", run->milliseconds,
          capture->frame, capture->ops.size(), qPrintable(capture->served.join(", ")),
          qPrintable(capture->refused.join(", ")), qPrintable(capture->errors.join(" | ")));
    QCOMPARE(capture->webgl, 1);
    QCOMPARE(capture->canvas, QSize(512, 512));
    QCOMPARE(capture->frame, 5);
    QVERIFY(capture->animated);
    QCOMPARE(capture->draws().size(), std::size_t(1));
    QVERIFY(capture->errors.isEmpty());
}

QTEST_GUILESS_MAIN(TestPageRun)
#include "tst_pagerun.moc"
