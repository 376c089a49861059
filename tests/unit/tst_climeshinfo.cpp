// `phonglab mesh-info` as scripts use it: the JSON keys, exit codes and the
// error line.
#include "PhonglabProcess.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab::test;

namespace {

ProcessRun meshInfo(const QStringList &args)
{
    return runPhonglab(QStringList{QStringLiteral("mesh-info")} + args, 60000);
}

QString blender(const QString &name)
{
    return QStringLiteral(PHONGLAB_TEST_DATA_DIR "/meshes/blender/") + name;
}

} // namespace

class TestCliMeshInfo : public QObject
{
    Q_OBJECT

private slots:
    void jsonHasTheDocumentedKeys();
    void normalsFromFileOrComputed();
    void textOutputMentionsEverything();
    void unloadableFileExitsOne();
    void usageErrorsExitTwo_data();
    void usageErrorsExitTwo();
};

void TestCliMeshInfo::jsonHasTheDocumentedKeys()
{
    const ProcessRun r =
        meshInfo({blender(QStringLiteral("cube_flat.obj")), QStringLiteral("--json")});
    QCOMPARE(r.exitCode, 0);
    QJsonParseError error;
    const QJsonObject o = QJsonDocument::fromJson(r.out, &error).object();
    QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(error.errorString()));
    for (const char *key :
         {"vertices", "faces", "normals", "normal_method", "bounds", "warnings", "load_ms"})
        QVERIFY2(o.contains(QLatin1String(key)), key);
    QCOMPARE(o.value("vertices").toInt(), 8);
    QCOMPARE(o.value("faces").toInt(), 6);
    QCOMPARE(o.value("normals").toString(), QStringLiteral("file"));
    QCOMPARE(o.value("split_vertices").toInt(), 16);
    QVERIFY(o.value("warnings").isArray());
    QVERIFY(o.value("load_ms").toDouble() >= 0.0);
    const QJsonArray min = o.value("bounds").toObject().value("min").toArray();
    const QJsonArray max = o.value("bounds").toObject().value("max").toArray();
    for (int i = 0; i < 3; ++i) {
        QCOMPARE(min[i].toDouble(), -1.0);
        QCOMPARE(max[i].toDouble(), 1.0);
    }
}

void TestCliMeshInfo::normalsFromFileOrComputed()
{
    const ProcessRun none =
        meshInfo({blender(QStringLiteral("sphere_nonormals.obj")), QStringLiteral("--json")});
    QCOMPARE(none.exitCode, 0);
    QJsonObject o = QJsonDocument::fromJson(none.out).object();
    QCOMPARE(o.value("normals").toString(), QStringLiteral("computed"));
    QCOMPARE(o.value("normal_method").toString(), QStringLiteral("angle"));

    const ProcessRun forced =
        meshInfo({blender(QStringLiteral("sphere_smooth.obj")), QStringLiteral("--json"),
                  QStringLiteral("--normals"), QStringLiteral("area"), QStringLiteral("--crease"),
                  QStringLiteral("45")});
    QCOMPARE(forced.exitCode, 0);
    o = QJsonDocument::fromJson(forced.out).object();
    QCOMPARE(o.value("normals").toString(), QStringLiteral("computed"));
    QCOMPARE(o.value("normal_method").toString(), QStringLiteral("area"));
    QCOMPARE(o.value("crease_deg").toDouble(), 45.0);
}

void TestCliMeshInfo::textOutputMentionsEverything()
{
    const ProcessRun r = meshInfo({blender(QStringLiteral("cube_flat.obj"))});
    QCOMPARE(r.exitCode, 0);
    for (const char *word :
         {"vertices:", "faces:", "normals:", "bounds:", "warnings:", "load time:", "split"})
        QVERIFY2(r.out.contains(word), word);
}

void TestCliMeshInfo::unloadableFileExitsOne()
{
    QTemporaryDir dir;
    const QString empty = dir.filePath(QStringLiteral("empty.obj"));
    QFile(empty).open(QIODevice::WriteOnly);
    for (const QString &path : {empty, dir.filePath(QStringLiteral("missing.ply"))}) {
        const ProcessRun r = meshInfo({path, QStringLiteral("--json")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.startsWith(QStringLiteral("phonglab: error: ")), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }
}

void TestCliMeshInfo::usageErrorsExitTwo_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("no file") << QStringList();
    QTest::newRow("two files") << QStringList{blender(QStringLiteral("cube_flat.obj")),
                                              blender(QStringLiteral("cube_flat.obj"))};
    QTest::newRow("unknown method")
        << QStringList{blender(QStringLiteral("cube_flat.obj")), QStringLiteral("--normals"),
                       QStringLiteral("smooth")};
    QTest::newRow("bad crease") << QStringList{blender(QStringLiteral("cube_flat.obj")),
                                               QStringLiteral("--crease"), QStringLiteral("200")};
}

void TestCliMeshInfo::usageErrorsExitTwo()
{
    QFETCH(QStringList, args);
    const ProcessRun r = meshInfo(args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains(QStringLiteral("phonglab: error: ")));
}

QTEST_GUILESS_MAIN(TestCliMeshInfo)
#include "tst_climeshinfo.moc"
