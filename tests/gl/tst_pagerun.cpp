// A student's page run in headless Chromium (core/page/PageRun) and what
// its capture holds (core/page/PageCapture): the test projects of
// tests/data/pages, each made to show one thing a real course page does.
#include "TestPaths.h"
#include "core/page/BrowserPipe.h"
#include "core/page/PageCapture.h"
#include "core/page/PageFidelity.h"
#include "core/page/PageMatrices.h"
#include "core/page/PageNormals.h"
#include "core/page/PageRun.h"
#include "mesh/import/MeshLoader.h"
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
                                 sourcePath(QStringLiteral("assets/meshes"))};
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
    void normalsAndNormalMatrixAreNamed_data();
    void normalsAndNormalMatrixAreNamed();

private:
    PageFidelity replayed(const PageCapture &capture);

    OffscreenRenderer m_offscreen;
    std::optional<PageCapture> m_angel;
    std::vector<CourseMesh> m_courseMeshes;
};

void TestPageRun::initTestCase()
{
    if (BrowserPipe::executable().isEmpty())
        QSKIP("chromium is not installed (scripts/setup.sh installs it)");
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
    QVERIFY(m_offscreen.create().ok());
    for (const QString &name : {QStringLiteral("cloud.obj"), QStringLiteral("tree.obj")}) {
        const MeshLoadResult loaded = loadMesh(sourcePath(QStringLiteral("assets/meshes/") + name));
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        m_courseMeshes.push_back({name, *loaded.mesh});
    }
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
    QVERIFY(fidelity.edgePixels < 512 * 512 / 10);
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

// The JavaScript half: each select of the test page sends one mistake, and
// the capture names it, with the line of phong.js that sent it.
void TestPageRun::normalsAndNormalMatrixAreNamed_data()
{
    QTest::addColumn<QStringList>("steps");
    QTest::addColumn<QString>("cloud");
    QTest::addColumn<QString>("normalMatrix");
    QTest::newRow("right") << QStringList{} << "normals-exact"
                           << "normal-matrix-right";
    QTest::newRow("face") << QStringList{"select #normals=face"} << "normals-face"
                          << "normal-matrix-right";
    QTest::newRow("long") << QStringList{"select #normals=long"} << "normals-not-normalised"
                          << "normal-matrix-right";
    QTest::newRow("positions") << QStringList{"select #normals=positions"} << "normals-positions"
                               << "normal-matrix-right";
    QTest::newRow("transpose") << QStringList{"select #normalMatrix=transpose"} << "normals-exact"
                               << "normal-matrix-transpose";
}

void TestPageRun::normalsAndNormalMatrixAreNamed()
{
    QFETCH(QStringList, steps);
    QFETCH(QString, cloud);
    QFETCH(QString, normalMatrix);
    PageCapture capture;
    if (steps.isEmpty()) {
        QVERIFY(m_angel);
        capture = *m_angel;
    } else {
        PageRunOptions options = pageOptions(QStringLiteral("angel"));
        options.steps = steps;
        options.frames = 1;
        const Result<PageRunOutput> run = runPage(options);
        QVERIFY2(run.ok(), qPrintable(run.error()));
        capture = readPageCapture(run->capture).value();
        QCOMPARE(capture.steps.size(), std::size_t(1));
        QVERIFY2(capture.steps.front().problem.isEmpty(),
                 qPrintable(capture.steps.front().problem));
    }
    const std::vector<JavaScriptFinding> normals = checkPageNormals(capture, m_courseMeshes);
    QCOMPARE(normals.size(), std::size_t(2));
    QCOMPARE(normals[0].subject, QStringLiteral("cloud.obj"));
    QCOMPARE(normals[0].key, cloud);
    QCOMPARE(normals[0].mistake, cloud != QLatin1String("normals-exact"));
    QVERIFY2(normals[0].where.startsWith(QLatin1String("phong.js:")), qPrintable(normals[0].where));
    QCOMPARE(normals[1].key, QStringLiteral("normals-missing")); // the tree is not drawn
    const std::vector<JavaScriptFinding> matrices = checkPageMatrices(capture);
    QCOMPARE(matrices.size(), std::size_t(1));
    QCOMPARE(matrices[0].key, normalMatrix);
    QCOMPARE(matrices[0].subject, QStringLiteral("normalMatrix"));
    QVERIFY2(matrices[0].where.startsWith(QLatin1String("phong.js:")),
             qPrintable(matrices[0].where));
}

QTEST_MAIN(TestPageRun)
#include "tst_pagerun.moc"
