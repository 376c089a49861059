// The per-object "normals" field of scene files: how a mesh gets its normals.
#include "core/scene/SceneJson.h"

#include <QTest>

using namespace phonglab;

namespace {
QByteArray sceneWith(const QByteArray &normals)
{
    return R"({"mesh": "builtin:sphere", "normals": )" + normals + "}";
}
} // namespace

class TestSceneNormals : public QObject
{
    Q_OBJECT

private slots:
    void defaultIsAuto();
    void readsForms_data();
    void readsForms();
    void roundTrips();
    void perObjectInObjectsList();
    void refusesBadValues_data();
    void refusesBadValues();
};

void TestSceneNormals::defaultIsAuto()
{
    const SceneLoadResult r = parseScene(R"({"mesh": "builtin:sphere"})");
    QVERIFY(r.ok());
    QCOMPARE(r.scene->objects[0].normals, NormalOptions{});
    // Defaults are not written, so old readers see the familiar form.
    QVERIFY(!sceneToJson(*r.scene).contains("\"normals\""));
}

void TestSceneNormals::readsForms_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<int>("method");
    QTest::addColumn<double>("crease"); // < 0: none
    QTest::newRow("string flat") << QByteArray(R"("flat")") << int(NormalMethod::Flat) << -1.0;
    QTest::newRow("string average")
        << QByteArray(R"("average")") << int(NormalMethod::Average) << -1.0;
    QTest::newRow("string area") << QByteArray(R"("area")") << int(NormalMethod::AreaWeighted)
                                 << -1.0;
    QTest::newRow("string angle") << QByteArray(R"("angle")") << int(NormalMethod::AngleWeighted)
                                  << -1.0;
    QTest::newRow("object with crease") << QByteArray(R"({"method": "area", "crease_deg": 40})")
                                        << int(NormalMethod::AreaWeighted) << 40.0;
    QTest::newRow("crease only") << QByteArray(R"({"crease_deg": 0})") << int(NormalMethod::Auto)
                                 << 0.0;
    QTest::newRow("null crease") << QByteArray(R"({"method": "flat", "crease_deg": null})")
                                 << int(NormalMethod::Flat) << -1.0;
}

void TestSceneNormals::readsForms()
{
    QFETCH(QByteArray, json);
    QFETCH(int, method);
    QFETCH(double, crease);
    const SceneLoadResult r = parseScene(sceneWith(json));
    QVERIFY2(r.ok(), qPrintable(r.error));
    const NormalOptions &n = r.scene->objects[0].normals;
    QCOMPARE(int(n.method), method);
    QCOMPARE(n.creaseAngleDeg.has_value(), crease >= 0.0);
    if (crease >= 0.0)
        QCOMPARE(*n.creaseAngleDeg, crease);
}

void TestSceneNormals::roundTrips()
{
    for (const QByteArray &json :
         {QByteArray(R"("flat")"), QByteArray(R"({"method": "angle", "crease_deg": 33.5})")}) {
        const SceneLoadResult first = parseScene(sceneWith(json));
        QVERIFY2(first.ok(), qPrintable(first.error));
        const SceneLoadResult again = parseScene(sceneToJson(*first.scene));
        QVERIFY2(again.ok(), qPrintable(again.error));
        QCOMPARE(again.scene->objects[0].normals, first.scene->objects[0].normals);
    }
}

void TestSceneNormals::perObjectInObjectsList()
{
    const SceneLoadResult r = parseScene(R"({"objects": [
        {"mesh": "builtin:sphere", "normals": "flat"},
        {"mesh": "builtin:torus"}]})");
    QVERIFY2(r.ok(), qPrintable(r.error));
    QCOMPARE(r.scene->objects[0].normals.method, NormalMethod::Flat);
    QCOMPARE(r.scene->objects[1].normals.method, NormalMethod::Auto);
    QVERIFY(r.warnings.isEmpty());
}

void TestSceneNormals::refusesBadValues_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("prefix");
    QTest::newRow("unknown method") << sceneWith(R"("smooth")") << "normals:";
    QTest::newRow("number") << sceneWith("3") << "normals:";
    QTest::newRow("method not a string") << sceneWith(R"({"method": 1})") << "normals.method:";
    QTest::newRow("negative crease") << sceneWith(R"({"crease_deg": -1})") << "normals.crease_deg:";
    QTest::newRow("crease over 180")
        << sceneWith(R"({"crease_deg": 181})") << "normals.crease_deg:";
    QTest::newRow("crease not a number")
        << sceneWith(R"({"crease_deg": "wide"})") << "normals.crease_deg:";
    QTest::newRow("crease overflow")
        << sceneWith(R"({"crease_deg": 1e999})") << "normals.crease_deg:";
    QTest::newRow("unknown key") << sceneWith(R"({"mode": "flat"})") << "normals.mode:";
    QTest::newRow("in objects list")
        << QByteArray(R"({"objects": [{"mesh": "builtin:sphere", "normals": "x"}]})")
        << "objects[0].normals:";
    QTest::newRow("top level with objects")
        << QByteArray(R"({"objects": [{"mesh": "builtin:sphere"}], "normals": "flat"})") << "";
}

void TestSceneNormals::refusesBadValues()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, prefix);
    const SceneLoadResult r = parseScene(json);
    if (prefix.isEmpty()) { // ignored with a warning, like top-level transform/material
        QVERIFY(r.ok());
        QVERIFY(!r.warnings.isEmpty());
        return;
    }
    QVERIFY(!r.ok());
    QVERIFY2(r.error.startsWith(prefix), qPrintable(r.error));
}

QTEST_APPLESS_MAIN(TestSceneNormals)
#include "tst_scenenormals.moc"
