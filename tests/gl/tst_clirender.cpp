// `phonglab render` as a script sees it: exit codes, stderr, and no output
// file unless everything succeeded.
#include "PhonglabProcess.h"
#include "RenderCheck.h"
#include "TestPaths.h"

#include <QImage>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab::test;

class TestCliRender : public QObject
{
    Q_OBJECT

private slots:
    void helpListsSubcommands();
    void rendersPng();
    void rendersDefaultScene();
    void usageErrors_data();
    void usageErrors();
    void badInputFails_data();
    void badInputFails();
    void compileErrorPointsAtUserLine();
    void sceneShadersAreUsed();

private:
    QTemporaryDir m_dir;
};

void TestCliRender::helpListsSubcommands()
{
    const ProcessRun r = runPhonglab({QStringLiteral("--help")});
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(QString::fromLocal8Bit(r.out).contains(QStringLiteral("render")), r.out.constData());
    const ProcessRun sub = runPhonglab({QStringLiteral("render"), QStringLiteral("--help")});
    QCOMPARE(sub.exitCode, 0);
    QVERIFY(QString::fromLocal8Bit(sub.out).contains(QStringLiteral("--size")));
}

void TestCliRender::rendersPng()
{
    const QString out = m_dir.filePath(QStringLiteral("sphere.png"));
    const ProcessRun r = runPhonglab(
        {QStringLiteral("render"), testDataPath(QStringLiteral("scenes/gl_sphere_one_light.json")),
         QStringLiteral("-o"), out, QStringLiteral("--size"), QStringLiteral("160x120")});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QImage image(out);
    QCOMPARE(image.size(), QSize(160, 120));
    QVERIFY(!image.hasAlphaChannel());
    // 8-bit RGB on disk: the PNG header's IHDR says bit depth 8, colour type 2.
    QFile file(out);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray header = file.read(26);
    QCOMPARE(header.mid(12, 4), QByteArray("IHDR"));
    QCOMPARE(int(header[24]), 8);
    QCOMPARE(int(header[25]), 2);
    // The sphere is lit in the middle and the corner is the background
    // (0.1, 0.1, 0.12) -> (26, 26, 31).
    QCOMPARE(image.pixelColor(0, 0), QColor(26, 26, 31));
    QVERIFY(image.pixelColor(80, 60) != QColor(26, 26, 31));
}

void TestCliRender::rendersDefaultScene()
{
    const QString out = m_dir.filePath(QStringLiteral("default.png"));
    const ProcessRun r = runPhonglab(
        {QStringLiteral("render"), sourcePath(QStringLiteral("assets/scenes/default.json")),
         QStringLiteral("-o"), out, QStringLiteral("--size"), QStringLiteral("64x48")});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY(QFile::exists(out));
}

void TestCliRender::usageErrors_data()
{
    QTest::addColumn<QStringList>("args");
    const QString scene = testDataPath(QStringLiteral("scenes/gl_sphere_one_light.json"));
    QTest::newRow("no scene") << QStringList{QStringLiteral("render"), QStringLiteral("-o"),
                                             QStringLiteral("x.png")};
    QTest::newRow("no output") << QStringList{QStringLiteral("render"), scene};
    QTest::newRow("two scenes") << QStringList{QStringLiteral("render"), scene, scene,
                                               QStringLiteral("-o"), QStringLiteral("x.png")};
    QTest::newRow("bad size") << QStringList{QStringLiteral("render"), scene,
                                             QStringLiteral("-o"),     QStringLiteral("x.png"),
                                             QStringLiteral("--size"), QStringLiteral("12by4")};
    QTest::newRow("zero size") << QStringList{QStringLiteral("render"), scene,
                                              QStringLiteral("-o"),     QStringLiteral("x.png"),
                                              QStringLiteral("--size"), QStringLiteral("0x10")};
    QTest::newRow("huge size") << QStringList{
        QStringLiteral("render"), scene,
        QStringLiteral("-o"),     QStringLiteral("x.png"),
        QStringLiteral("--size"), QStringLiteral("100000x10")};
    QTest::newRow("unknown option")
        << QStringList{QStringLiteral("render"), scene, QStringLiteral("-o"),
                       QStringLiteral("x.png"), QStringLiteral("--frobnicate")};
    QTest::newRow("unknown top-level option") << QStringList{QStringLiteral("--frobnicate")};
}

void TestCliRender::usageErrors()
{
    QFETCH(QStringList, args);
    const ProcessRun r = runPhonglab(args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QStringLiteral("phonglab: error: ")), qPrintable(r.err));
    QVERIFY(!QFile::exists(QStringLiteral("x.png")));
}

void TestCliRender::badInputFails_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QStringList>("extra");
    QTest::addColumn<QString>("expected"); // part of the error message
    QTest::newRow("missing scene file")
        << m_dir.filePath(QStringLiteral("nope.json")) << QStringList() << "nope.json";
    QTest::newRow("unknown builtin mesh") << testDataPath(QStringLiteral("scenes/gl_bad_mesh.json"))
                                          << QStringList() << "builtin:cylinder";
    QTest::newRow("missing shader file")
        << testDataPath(QStringLiteral("scenes/gl_sphere_one_light.json"))
        << QStringList{QStringLiteral("--fragment"), m_dir.filePath(QStringLiteral("missing.frag"))}
        << "missing.frag";
    QTest::newRow("unwritable output")
        << testDataPath(QStringLiteral("scenes/gl_sphere_one_light.json"))
        << QStringList{QStringLiteral("-o"), QStringLiteral("/nonexistent-dir/out.png")}
        << "/nonexistent-dir/out.png";
}

void TestCliRender::badInputFails()
{
    QFETCH(QString, scene);
    QFETCH(QStringList, extra);
    QFETCH(QString, expected);
    const QString out = m_dir.filePath(QStringLiteral("bad.png"));
    QStringList args{QStringLiteral("render"), scene};
    if (!extra.contains(QStringLiteral("-o")))
        args << QStringLiteral("-o") << out;
    args << extra;
    const ProcessRun r = runPhonglab(args);
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("phonglab: error: ")), qPrintable(r.err));
    QVERIFY2(r.err.contains(expected), qPrintable(r.err));
    QVERIFY(!QFile::exists(out));
}

void TestCliRender::compileErrorPointsAtUserLine()
{
    const QString out = m_dir.filePath(QStringLiteral("broken.png"));
    const QString frag = testDataPath(QStringLiteral("shaders/error_line17.frag"));
    const ProcessRun r = runPhonglab(
        {QStringLiteral("render"), testDataPath(QStringLiteral("scenes/gl_sphere_one_light.json")),
         QStringLiteral("-o"), out, QStringLiteral("--fragment"), frag});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(frag + QStringLiteral(":17:9: error: ")), qPrintable(r.err));
    QVERIFY(!QFile::exists(out));
}

void TestCliRender::sceneShadersAreUsed()
{
    // A scene naming its own fragment shader (relative to the scene file)
    // renders with it; --shading picks the shipped method instead.
    QFile shipped(sourcePath(QStringLiteral("shaders/phong.frag")));
    QVERIFY(shipped.open(QIODevice::ReadOnly));
    QByteArray swapped = shipped.readAll();
    QVERIFY(swapped.contains("fragColor = vec4(I, 1.0);"));
    swapped.replace("fragColor = vec4(I, 1.0);", "fragColor = vec4(I.bgr, 1.0);");
    QFile frag(m_dir.filePath(QStringLiteral("swap.frag")));
    QVERIFY(frag.open(QIODevice::WriteOnly) && frag.write(swapped) == swapped.size());
    frag.close();
    QFile scene(m_dir.filePath(QStringLiteral("own-shader.json")));
    QVERIFY(scene.open(QIODevice::WriteOnly));
    scene.write(R"({"mesh": "builtin:sphere", "material": {"kd": [0.9, 0.1, 0.1]},
                    "lights": [{"position": [3, 3, 4]}], "shaders": {"fragment": "swap.frag"}})");
    scene.close();

    const QString own = m_dir.filePath(QStringLiteral("own.png"));
    const QString method = m_dir.filePath(QStringLiteral("method.png"));
    QCOMPARE(runPhonglab({QStringLiteral("render"), scene.fileName(), QStringLiteral("-o"), own,
                          QStringLiteral("--size"), QStringLiteral("64x64")})
                 .exitCode,
             0);
    QCOMPARE(runPhonglab({QStringLiteral("render"), scene.fileName(), QStringLiteral("-o"), method,
                          QStringLiteral("--size"), QStringLiteral("64x64"),
                          QStringLiteral("--shading"), QStringLiteral("phong")})
                 .exitCode,
             0);
    const QColor a = QImage(own).pixelColor(32, 32), b = QImage(method).pixelColor(32, 32);
    QVERIFY2(b.red() > b.blue(), "the shipped Phong shader shows the red material");
    QCOMPARE(a.red(), b.blue()); // the scene's shader swapped the channels
    QCOMPARE(a.blue(), b.red());
}

QTEST_GUILESS_MAIN(TestCliRender)
#include "tst_clirender.moc"
