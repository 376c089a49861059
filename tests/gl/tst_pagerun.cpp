// A student's page run in headless Chromium (core/page/PageRun) and what
// its capture holds (core/page/PageCapture): the test projects of
// tests/data/pages, each made to show one thing a real course page does.
#include "TestPaths.h"
#include "core/page/BrowserPipe.h"
#include "core/page/PageCapture.h"
#include "core/page/PageFidelity.h"
#include "core/page/PageRun.h"
#include "render/GlFormat.h"
#include "render/OffscreenRenderer.h"
#include "render/page/PageReplay.h"

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
    void replayDrawsTheBrowsersPixels();
    void aChangedUniformIsNotFaithful();

private:
    PageFidelity replayed(const PageCapture &capture);

    OffscreenRenderer m_offscreen;
    std::optional<PageCapture> m_angel;
};

void TestPageRun::initTestCase()
{
    if (BrowserPipe::executable().isEmpty())
        QSKIP("chromium is not installed (scripts/setup.sh installs it)");
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
    QVERIFY(m_offscreen.create().ok());
}

PageFidelity TestPageRun::replayed(const PageCapture &capture)
{
    m_offscreen.makeCurrent();
    const Result<ReplayedFrame> frame = replayCapture(capture);
    if (!frame) {
        qWarning("replay failed: %s", qPrintable(frame.error()));
        return {};
    }
    if (!frame->notReplayed.isEmpty())
        qWarning("not replayed: %s", qPrintable(frame->notReplayed.join(" | ")));
    return comparePageFrames(capture.pixels, frame->pixels, capture.canvas);
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
    m_angel = *capture;
}

void TestPageRun::replayDrawsTheBrowsersPixels()
{
    QVERIFY(m_angel);
    const PageFidelity fidelity = replayed(*m_angel);
    qInfo("fidelity: largest difference %d outside edges (%lld edge pixels), %d anywhere",
          fidelity.largestOutsideEdges, fidelity.edgePixels, fidelity.largestAnywhere);
    QVERIFY(fidelity.faithful());
    QVERIFY(fidelity.edgePixels < 512 * 512 / 20);
}

// The control: the same capture with the shininess the page did not send
// must fail the same comparison.
void TestPageRun::aChangedUniformIsNotFaithful()
{
    QVERIFY(m_angel);
    PageCapture changed = *m_angel;
    for (CapturedOp &op : changed.ops)
        for (CapturedUniform &u : op.uniforms)
            if (u.name == QLatin1String("shininess"))
                u.values = {{4.0}};
    const PageFidelity fidelity = replayed(changed);
    qInfo("with shininess 4: largest difference %d outside edges", fidelity.largestOutsideEdges);
    QVERIFY(!fidelity.faithful());
}

QTEST_MAIN(TestPageRun)
#include "tst_pagerun.moc"
