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
#include "core/page/PageScene.h"
#include "mesh/loading/MeshLoader.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/GlFormat.h"
#include "render/page/PageReplay.h"

#include <QElapsedTimer>
#include <QFileInfo>
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
    void webgl2IndexedDrawnOnce();
    void threeJsShaderMaterial();
    void aPageThatNeverDraws();
    void anEndlessLoopEndsAtTheTimeLimit();
    void networkAttemptsAreRefusedAndListed();
    void timersAndClockAreDeterministic();
    void timingTricksOfRealPages();
    void theOwnSceneMatchesTheExactImage();
    void theOwnSceneFailsWhatIsWrong();
    void anOwnSceneThatCannotBeReadSaysWhy();

private:
    PageFidelity replayed(const PageCapture &capture);

    OffscreenRenderer m_offscreen;
    std::optional<PageCapture> m_angel;
    std::optional<PageCapture> m_webgl2;
    std::optional<PageCapture> m_three;
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

// webgl2fundamentals' style: WebGL 2, a vertex array and an index buffer,
// one draw once fetch() has brought the mesh, no animation (frame 0).
void TestPageRun::webgl2IndexedDrawnOnce()
{
    const Result<PageRunOutput> run = runPage(pageOptions(QStringLiteral("webgl2fundamentals")));
    QVERIFY2(run.ok(), qPrintable(run.error()));
    const PageCapture capture = readPageCapture(run->capture).value();
    QCOMPARE(capture.webgl, 2);
    QCOMPARE(capture.frame, 0);
    QVERIFY(!capture.animated);
    QCOMPARE(capture.draws().size(), std::size_t(1));
    QVERIFY(capture.draws().front()->indexed());
    const PageFidelity fidelity = replayed(capture);
    qInfo("webgl2fundamentals: %lld ms, largest difference %d outside edges", run->milliseconds,
          fidelity.largestOutsideEdges);
    QVERIFY(fidelity.faithful());
    m_webgl2 = capture;
    const std::vector<JavaScriptFinding> normals = checkPageNormals(capture, m_courseMeshes);
    QCOMPARE(normals[1].subject, QStringLiteral("tree.obj"));
    QCOMPARE(normals[1].key, QStringLiteral("normals-exact"));
    const std::vector<JavaScriptFinding> matrices = checkPageMatrices(capture);
    QCOMPARE(matrices.size(), std::size_t(1));
    QCOMPARE(matrices[0].subject, QStringLiteral("u_worldInverseTranspose"));
    QCOMPARE(matrices[0].key, QStringLiteral("normal-matrix-right"));
}

// three.js r111 (Debian's libjs-three) from its CDN address, answered from
// the library folder by the file's name; the program as three.js compiled
// it, its prefix and the material's defines in front.
void TestPageRun::threeJsShaderMaterial()
{
    const QString three = QStringLiteral("/usr/share/javascript/three/build");
    if (!QFileInfo::exists(three + QStringLiteral("/three.min.js")))
        QSKIP("libjs-three is not installed (scripts/setup.sh installs it)");
    PageRunOptions options = pageOptions(QStringLiteral("threejs"));
    options.folders.libraries.push_back(three);
    const Result<PageRunOutput> run = runPage(options);
    QVERIFY2(run.ok(), qPrintable(run.error()));
    const PageCapture capture = readPageCapture(run->capture).value();
    QVERIFY2(capture.refused.isEmpty(), qPrintable(capture.refused.join(", ")));
    QVERIFY2(capture.served.filter(QStringLiteral("three.min.js")).size() == 1,
             qPrintable(capture.served.join(", ")));
    QCOMPARE(capture.draws().size(), std::size_t(1));
    const CapturedProgram *program = capture.program(capture.draws().front()->program);
    QVERIFY(program);
    QVERIFY(program->fragment.contains(QLatin1String("#define NUM_LIGHTS 1")));
    QVERIFY(program->vertex.contains(QLatin1String("uniform mat4 modelViewMatrix")));
    const PageFidelity fidelity = replayed(capture);
    qInfo("three.js: %lld ms, largest difference %d outside edges", run->milliseconds,
          fidelity.largestOutsideEdges);
    QVERIFY(fidelity.faithful());
    m_three = capture;
    const std::vector<JavaScriptFinding> matrices = checkPageMatrices(capture);
    QVERIFY(!matrices.empty());
    QCOMPARE(matrices[0].key, QStringLiteral("normal-matrix-right"));
}

void TestPageRun::aPageThatNeverDraws()
{
    const Result<PageRunOutput> run = runPage(pageOptions(QStringLiteral("never-draws")));
    QVERIFY2(run.ok(), qPrintable(run.error()));
    const PageCapture capture = readPageCapture(run->capture).value();
    QCOMPARE(capture.webgl, 1);
    QVERIFY(capture.draws().empty());
    QVERIFY(capture.pixels.isEmpty());
    m_offscreen.makeCurrent();
    QVERIFY(!replayCapture(capture).ok());
}

// A script that never ends holds neither the run nor the caller past the
// time limit (the page's, counted from the browser's start).
void TestPageRun::anEndlessLoopEndsAtTheTimeLimit()
{
    PageRunOptions options = pageOptions(QStringLiteral("endless-loop"));
    options.timeLimitMs = 4000;
    QElapsedTimer clock;
    clock.start();
    const Result<PageRunOutput> run = runPage(options);
    qInfo("endless loop stopped after %lld ms: %s", clock.elapsed(), qPrintable(run.error()));
    QVERIFY(!run.ok());
    QVERIFY(run.error().contains(QLatin1String("did not finish within 4 s")));
    // The limit starts once the browser is up: its start (1–3 s) comes first.
    QVERIFY(clock.elapsed() < 4000 + 6000);
}

// Every kind of network access gets nothing and is listed; a path that
// climbs out of the project is refused; the page still draws.
void TestPageRun::networkAttemptsAreRefusedAndListed()
{
    const Result<PageRunOutput> run = runPage(pageOptions(QStringLiteral("network")));
    QVERIFY2(run.ok(), qPrintable(run.error()));
    const PageCapture capture = readPageCapture(run->capture).value();
    const QString refused = capture.refused.join(QLatin1Char('\n'));
    qInfo("refused:\n%s", qPrintable(refused));
    for (const char *expected :
         {"request https://scripts.example.com/analytics.js",
          "request http://styles.example.com/theme.css",
          "request http://images.example.com/logo.png", "request https://api.example.com/fetch",
          "request http://api.example.com/xhr", "WebSocket wss://socket.example.com/",
          "EventSource https://events.example.com/", "sendBeacon https://beacon.example.com/"})
        QVERIFY2(refused.contains(QLatin1String(expected)), expected);
    QCOMPARE(capture.served, QStringList{QStringLiteral("index.html")});
    QVERIFY(!capture.pixels.isEmpty());
    QCOMPARE(int(quint8(capture.pixels[1])), 128); // the green it cleared to
}

// Two runs of a page animated by setInterval, coloured by Date.now() and
// Math.random(): the same frame, byte for byte. It clears only the colour
// buffer; its triangle shows in frame 5 only because the browser's clear
// of depth after each frame is kept.
void TestPageRun::timersAndClockAreDeterministic()
{
    const Result<PageRunOutput> first = runPage(pageOptions(QStringLiteral("timers")));
    const Result<PageRunOutput> second = runPage(pageOptions(QStringLiteral("timers")));
    QVERIFY2(first.ok() && second.ok(), qPrintable(first.error() + second.error()));
    const PageCapture a = readPageCapture(first->capture).value();
    const PageCapture b = readPageCapture(second->capture).value();
    QCOMPARE(a.frame, 5);
    QVERIFY(a.animated);
    QCOMPARE(a.pixels, b.pixels);
    QCOMPARE(a.draws().front()->uniforms.front().values,
             b.draws().front()->uniforms.front().values);
    const qsizetype centre = (qsizetype(32) * 96 + 48) * 4;
    QVERIFY(quint8(a.pixels[centre + 2]) > 100); // blue 0.5: the triangle, not the clear colour
    QVERIFY(replayed(a).faithful());
}

// What real pages do and a browser lives with: a probe context on a canvas
// of its own, an endless chain of zero timeouts, a wait in a loop for the
// clock, a drawing that starts after the first frames, a script whose file
// name holds a '%'. The run ends, and the frame is the drawing's.
void TestPageRun::timingTricksOfRealPages()
{
    const Result<PageRunOutput> run = runPage(pageOptions(QStringLiteral("tricky")));
    QVERIFY2(run.ok(), qPrintable(run.error()));
    const PageCapture capture = readPageCapture(run->capture).value();
    QVERIFY2(capture.errors.isEmpty(), qPrintable(capture.errors.join(" | ")));
    QCOMPARE(capture.extraContexts, 1);
    QCOMPARE(capture.canvas, QSize(64, 48));
    QCOMPARE(capture.draws().size(), std::size_t(1));
    QCOMPARE(callSiteText(capture.draws().front()->stack).section(QLatin1Char(':'), 0, 0),
             QStringLiteral("50%.js"));
    QVERIFY(capture.frame > 5); // setTimeout(init, 300): frame 18 or so
    QCOMPARE(int(quint8(capture.pixels[(qsizetype(24) * 64 + 32) * 4])), 255); // the triangle
    QVERIFY(replayed(capture).faithful());
}

// The student's own scene, read from the capture (meshes from the buffers,
// camera from the projection, lights and material from the uniforms),
// against the browser's pixels: the Angel-style page with Blender's normals
// and with face normals (its own geometry: exact either way), three.js.
void TestPageRun::theOwnSceneMatchesTheExactImage()
{
    QVERIFY(m_angel);
    const Result<PageSceneCheck> angel = checkPageScene(*m_angel);
    QVERIFY2(angel.ok(), qPrintable(angel.error()));
    qInfo("Angel-style page, its own scene: %s", qPrintable(checkSummary(angel->report)));
    QVERIFY(angel->report.passed());
    PageRunOptions options = pageOptions(QStringLiteral("angel"));
    options.steps = {QStringLiteral("select #normals=face")};
    options.frames = 1;
    const Result<PageRunOutput> faceted = runPage(options);
    QVERIFY2(faceted.ok(), qPrintable(faceted.error()));
    const Result<PageSceneCheck> face = checkPageScene(readPageCapture(faceted->capture).value());
    QVERIFY2(face.ok(), qPrintable(face.error()));
    qInfo("with face normals: %s", qPrintable(checkSummary(face->report)));
    QVERIFY(face->report.passed());
    if (!m_three)
        QSKIP("the three.js page did not run");
    const Result<PageSceneCheck> three = checkPageScene(*m_three);
    QVERIFY2(three.ok(), qPrintable(three.error()));
    qInfo("three.js page, its own scene: %s", qPrintable(checkSummary(three->report)));
    QVERIFY(three->report.passed());
}

// The controls: a shininess the page did not send, and a normal matrix
// sent transposed, fail the same comparison.
void TestPageRun::theOwnSceneFailsWhatIsWrong()
{
    QVERIFY(m_angel);
    PageCapture changed = *m_angel;
    for (CapturedOp &op : changed.ops)
        for (CapturedUniform &u : op.uniforms)
            if (u.name == QLatin1String("shininess"))
                u.values = {{4.0}};
    const Result<PageSceneCheck> shininess = checkPageScene(changed);
    QVERIFY2(shininess.ok(), qPrintable(shininess.error()));
    qInfo("with shininess 4 read: %s", qPrintable(checkSummary(shininess->report)));
    QVERIFY(!shininess->report.passed());
    PageRunOptions options = pageOptions(QStringLiteral("angel"));
    options.steps = {QStringLiteral("select #normalMatrix=transpose")};
    options.frames = 1;
    const Result<PageRunOutput> run = runPage(options);
    QVERIFY2(run.ok(), qPrintable(run.error()));
    const Result<PageSceneCheck> transposed = checkPageScene(readPageCapture(run->capture).value());
    QVERIFY2(transposed.ok(), qPrintable(transposed.error()));
    qInfo("with the normal matrix transposed: %s", qPrintable(checkSummary(transposed->report)));
    QVERIFY(!transposed->report.passed());
}

void TestPageRun::anOwnSceneThatCannotBeReadSaysWhy()
{
    QVERIFY(m_webgl2);
    const Result<PageSceneCheck> webgl2 = checkPageScene(*m_webgl2);
    QVERIFY(!webgl2.ok());
    QVERIFY2(webgl2.error().contains(QLatin1String("no projection of its own")),
             qPrintable(webgl2.error()));
    PageCapture unread = *m_angel;
    for (CapturedOp &op : unread.ops)
        for (CapturedUniform &u : op.uniforms)
            if (u.name == QLatin1String("shininess"))
                u.name = QStringLiteral("zork"); // a float no name or use binds
    const Result<PageSceneCheck> zork = checkPageScene(unread);
    QVERIFY(!zork.ok());
    QVERIFY2(zork.error().contains(QLatin1String("zork")), qPrintable(zork.error()));
}

QTEST_MAIN(TestPageRun)
#include "tst_pagerun.moc"
