// What a student's page is given while it runs (core/page/PageServer) and
// what a capture file may hold before PhongLab draws it again
// (core/page/PageCapture, core/page/CaptureBounds). Context-free.
#include "core/page/CaptureBounds.h"
#include "core/page/PageCapture.h"
#include "core/page/PageMatrices.h"
#include "core/page/PageServer.h"
#include "core/scene/SceneJson.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;

class TestPageServer : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void projectThenLibraries();
    void nothingOutsideTheFolders();
    void outsideAddresses();
    void captureErrorsAreLocated();
    void drawsPastTheirBuffersAreRefused();
    void aScenesPageSettingsRoundTrip();
    void aProductMustBeItsFactors();

private:
    void write(const QString &relative, const QByteArray &bytes = "x");

    QTemporaryDir m_dir;
    PageFolders m_folders;
};

void TestPageServer::write(const QString &relative, const QByteArray &bytes)
{
    const QString path = m_dir.filePath(relative);
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(bytes);
}

void TestPageServer::initTestCase()
{
    write(QStringLiteral("project/index.html"));
    write(QStringLiteral("project/js/main.js"));
    write(QStringLiteral("course/Common/initShaders.js"));
    write(QStringLiteral("course/gl-matrix-min.js"));
    write(QStringLiteral("secret.txt"));
    write(QStringLiteral("shared/lib.js"));
    QVERIFY(QFile::link(m_dir.filePath(QStringLiteral("secret.txt")),
                        m_dir.filePath(QStringLiteral("project/link.txt"))));
    QVERIFY(QFile::link(m_dir.filePath(QStringLiteral("shared/lib.js")),
                        m_dir.filePath(QStringLiteral("course/lib.js"))));
    m_folders.project = m_dir.filePath(QStringLiteral("project"));
    m_folders.libraries = {m_dir.filePath(QStringLiteral("course"))};
    m_folders.urlMap = {{QStringLiteral("https://cdn.example.org/three/"),
                         m_dir.filePath(QStringLiteral("course"))}};
}

void TestPageServer::projectThenLibraries()
{
    const auto served = [&](const char *path) {
        return serveRequest(m_folders, kPageOrigin + QLatin1String(path)).path;
    };
    QVERIFY(served("/index.html").endsWith(QLatin1String("project/index.html")));
    QVERIFY(served("/js/main.js").endsWith(QLatin1String("project/js/main.js")));
    // ../Common/initShaders.js from the page is /Common/initShaders.js
    QVERIFY(
        served("/Common/initShaders.js").endsWith(QLatin1String("course/Common/initShaders.js")));
    // A library's link may lead out of it (Debian's libjs-* are links).
    QVERIFY(served("/lib.js").endsWith(QLatin1String("shared/lib.js")));
    QCOMPARE(mimeTypeOfFile(QStringLiteral("a.js")), QStringLiteral("text/javascript"));
    QCOMPARE(mimeTypeOfFile(QStringLiteral("a.OBJ")), QStringLiteral("text/plain"));
}

void TestPageServer::nothingOutsideTheFolders()
{
    for (const char *path : {"/../secret.txt", "/%2e%2e/secret.txt", "/link.txt", "/missing.js",
                             "/js/../../secret.txt"}) {
        const ServedFile f = serveRequest(m_folders, kPageOrigin + QLatin1String(path));
        QVERIFY2(!f.served(), path);
        QVERIFY(!f.refusal.isEmpty());
    }
}

void TestPageServer::outsideAddresses()
{
    QVERIFY(!serveRequest(m_folders, QStringLiteral("https://example.com/data.json")).served());
    QVERIFY(!serveRequest(m_folders, QStringLiteral("ws://example.com/")).served());
    // A CDN's copy of a library the teacher holds: by its file name.
    QVERIFY(
        serveRequest(m_folders,
                     QStringLiteral("https://cdnjs.example.net/gl-matrix/2.8.1/gl-matrix-min.js"))
            .path.endsWith(QLatin1String("course/gl-matrix-min.js")));
    QVERIFY(serveRequest(m_folders,
                         QStringLiteral("https://cdn.example.org/three/Common/initShaders.js"))
                .path.endsWith(QLatin1String("course/Common/initShaders.js")));
    QVERIFY(!serveRequest(m_folders, QStringLiteral("https://cdn.example.org/three/../secret.txt"))
                 .served());
}

void TestPageServer::captureErrorsAreLocated()
{
    QVERIFY(readPageCapture("{").error().contains(QLatin1String("not JSON at byte")));
    QVERIFY(readPageCapture("{\"format\": 7}").error().contains(QLatin1String("format")));
    const Result<PageCapture> wrong =
        readPageCapture(R"({"format": 1, "canvas": {"width": 4, "height": 4}, "pixels": "AAAA"})");
    QVERIFY(!wrong.ok());
    QVERIFY(wrong.error().contains(QLatin1String("\"pixels\"")));
    QVERIFY(readPageCapture(R"({"format": 1})").ok()); // nothing drawn is a capture too
    // A number no real capture holds is no offset at all.
    const Result<PageCapture> huge = readPageCapture(
        R"({"format": 1, "draws": [{"op": "draw", "kind": "elements", "count": 3,
            "indexType": 5123, "offset": 9223372036854774784, "indices": "1:1"}]})");
    QVERIFY(huge.ok());
    QCOMPARE(huge->ops.front().offset, qint64(-1));
    QVERIFY(!drawOutOfBounds(*huge, huge->ops.front()).isEmpty());
    QString many = QStringLiteral(R"({"format": 1, "draws": [)");
    for (int i = 0; i <= int(kMaxCapturedOps); ++i)
        many += QStringLiteral(R"({"op": "clear", "mask": 16384},)");
    many.chop(1);
    many += QStringLiteral("]}");
    QVERIFY(readPageCapture(many.toUtf8())
                .error()
                .contains(QLatin1String("more than PhongLab checks")));
}

// A capture is a file anyone can hand PhongLab: a draw that would read
// past its buffers never reaches the driver.
void TestPageServer::drawsPastTheirBuffersAreRefused()
{
    PageCapture capture;
    capture.buffers[QStringLiteral("1:1")] = {QByteArray(3 * 3 * 4, '\0'), {}};
    capture.buffers[QStringLiteral("2:1")] = {QByteArray("\x00\x00\x01\x00\x07\x00", 6), {}};
    CapturedOp draw;
    CapturedAttribute position;
    position.name = QStringLiteral("p");
    position.enabled = true;
    position.buffer = QStringLiteral("1:1");
    position.size = 3;
    position.component = 0x1406;
    draw.attributes = {position};
    draw.count = 3;
    QCOMPARE(drawOutOfBounds(capture, draw), QString());
    draw.count = 4;
    QVERIFY(drawOutOfBounds(capture, draw).contains(QLatin1String("reads 48 bytes")));
    draw.count = 3;
    draw.indices = QStringLiteral("2:1");
    draw.indexType = 0x1403; // UNSIGNED_SHORT: 0, 1, 7
    QVERIFY(!drawOutOfBounds(capture, draw).isEmpty());
    draw.count = 2; // 0, 1
    QCOMPARE(drawOutOfBounds(capture, draw), QString());
    draw.offset = 1; // not a multiple of the index size
    QVERIFY(!drawOutOfBounds(capture, draw).isEmpty());
    draw.offset = 0;
    draw.count = 9; // more indices than the buffer holds
    QVERIFY(!drawOutOfBounds(capture, draw).isEmpty());
    draw.offset = qint64(1) << 62; // a sum with it would wrap past the check
    draw.count = 2;
    QVERIFY(!drawOutOfBounds(capture, draw).isEmpty());
    draw.offset = 0;
    draw.indices.clear();
    draw.indexType = 0;
    draw.attributes[0].offset = qint64(1) << 62;
    QVERIFY(!drawOutOfBounds(capture, draw).isEmpty());
    draw.attributes[0].offset = 0;
    draw.attributes[0].stride = 1 << 20; // WebGL allows 255
    QVERIFY(!drawOutOfBounds(capture, draw).isEmpty());
    draw.attributes[0].stride = 0;
    draw.indices = QStringLiteral("3:1"); // no such buffer
    draw.indexType = 0x1403;
    draw.count = 1;
    QVERIFY(!drawOutOfBounds(capture, draw).isEmpty());
}

// The scene's "page": what a teacher states once for the starter. Old
// scenes (none) load as before; every error is located.
void TestPageServer::aScenesPageSettingsRoundTrip()
{
    const QByteArray json = R"({"mesh": "sphere", "lights": [{"position": [1, 2, 3]}],
        "page": {"steps": ["select #shading=phong", "click #go"], "libraries": ["../course"],
                 "meshes": "../course/meshes", "frame": 3}})";
    const SceneLoadResult loaded = parseScene(json, m_dir.path());
    QVERIFY2(loaded.ok(), qPrintable(loaded.error));
    const PageSettings &page = loaded.scene->page;
    QCOMPARE(page.steps, (QStringList{"select #shading=phong", "click #go"}));
    QCOMPARE(page.libraries, QStringList{"../course"});
    QCOMPARE(page.meshes, QStringLiteral("../course/meshes"));
    QCOMPARE(page.frame, 3);
    const SceneLoadResult again = parseScene(sceneToJson(*loaded.scene), m_dir.path());
    QVERIFY2(again.ok(), qPrintable(again.error));
    QCOMPARE(again.scene->page, page);
    QVERIFY(parseScene(R"({"mesh": "sphere"})", m_dir.path()).scene->page.empty());
    for (const auto &[text, where] :
         {std::pair{R"({"mesh": "sphere", "page": {"steps": ["a", 2]}})", "page.steps[1]"},
          std::pair{R"({"mesh": "sphere", "page": {"frame": 0}})", "page.frame"},
          std::pair{R"({"mesh": "sphere", "page": {"stpes": []}})", "page.stpes"},
          std::pair{R"({"mesh": "sphere", "page": []})", "page"}}) {
        const SceneLoadResult wrong = parseScene(text, m_dir.path());
        QVERIFY(!wrong.ok());
        QVERIFY2(wrong.error.startsWith(QLatin1String(where)), qPrintable(wrong.error));
    }
}

// The page sends Ia·ka and, beside it, Ia and ka: the product must be theirs.
void TestPageServer::aProductMustBeItsFactors()
{
    PageCapture capture;
    CapturedOp draw;
    const auto uniform = [](const char *name, unsigned type, std::vector<double> value) {
        CapturedUniform u;
        u.name = QString::fromLatin1(name);
        u.glType = type;
        u.values = {std::move(value)};
        return u;
    };
    draw.uniforms = {uniform("ambientProduct", 0x8B52, {0.2, 0.2, 0.2, 1.0}),
                     uniform("Ia", 0x8B51, {0.5, 0.5, 0.5}),
                     uniform("ka", 0x8B51, {0.4, 0.4, 0.4})};
    capture.ops = {draw};
    QVERIFY(checkPageMatrices(capture).empty());
    capture.ops.front().uniforms[2].values = {{0.3, 0.4, 0.4}};
    const std::vector<JavaScriptFinding> found = checkPageMatrices(capture);
    QCOMPARE(found.size(), std::size_t(1));
    QCOMPARE(found.front().key, QStringLiteral("product-not-of-its-factors"));
    QVERIFY(found.front().mistake);
}

QTEST_GUILESS_MAIN(TestPageServer)
#include "tst_pageserver.moc"
