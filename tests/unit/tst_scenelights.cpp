// The optional per-light fields "name" and "enabled" of the scene format:
// defaults, round trip, written only when not the default, bad types.
#include "core/scene/SceneJson.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace phonglab;

namespace {

QByteArray withLights(const QByteArray &lights)
{
    return R"({"mesh": "builtin:sphere", "lights": )" + lights + "}";
}

QJsonArray lightsOf(const QByteArray &json)
{
    return QJsonDocument::fromJson(json).object().value(QStringLiteral("lights")).toArray();
}

} // namespace

class TestSceneLights : public QObject
{
    Q_OBJECT

private slots:
    void defaults()
    {
        const SceneLoadResult result = parseScene(withLights(R"([{"position": [1, 2, 3]}])"));
        QVERIFY2(result.ok(), qPrintable(result.error));
        QVERIFY(result.warnings.isEmpty());
        QVERIFY(result.scene->lights[0].name.empty());
        QVERIFY(result.scene->lights[0].enabled);
        QVERIFY(PointLight{}.enabled);
    }

    void readsNameAndEnabled()
    {
        const SceneLoadResult result = parseScene(withLights(
            R"([{"position": [1, 2, 3], "name": "Key light ☀", "enabled": false},
                {"position": [0, 0, 5], "enabled": true}])"));
        QVERIFY2(result.ok(), qPrintable(result.error));
        QVERIFY2(result.warnings.isEmpty(), qPrintable(result.warnings.join(u'\n')));
        QCOMPARE(QString::fromStdString(result.scene->lights[0].name),
                 QStringLiteral("Key light ☀"));
        QVERIFY(!result.scene->lights[0].enabled);
        QVERIFY(result.scene->lights[1].enabled);
        QVERIFY(result.scene->lights[1].name.empty());
    }

    void roundTripAndWrittenOnlyWhenNotDefault()
    {
        Scene scene = *parseScene(withLights(R"([{"position": [1, 2, 3]}, {"position": [3, 2, 1]},
                                                  {"position": [0, 4, 0]}])"))
                           .scene;
        scene.lights[0].name = "Rim";
        scene.lights[1].enabled = false;
        scene.lights[2].name = "Fill";
        scene.lights[2].enabled = false;
        const QByteArray json = sceneToJson(scene);
        const QJsonArray lights = lightsOf(json);
        QCOMPARE(lights.at(0).toObject().value(QStringLiteral("name")).toString(),
                 QStringLiteral("Rim"));
        QVERIFY(!lights.at(0).toObject().contains(QStringLiteral("enabled")));
        QVERIFY(!lights.at(1).toObject().contains(QStringLiteral("name")));
        QCOMPARE(lights.at(1).toObject().value(QStringLiteral("enabled")), QJsonValue(false));
        const SceneLoadResult back = parseScene(json);
        QVERIFY2(back.ok(), qPrintable(back.error));
        QVERIFY(back.scene->lights == scene.lights);

        // Defaults are not written: an old file stays byte-for-byte the same shape.
        scene.lights[0].name.clear();
        scene.lights[1].enabled = true;
        scene.lights[2] = PointLight{};
        for (const QJsonValue &light : lightsOf(sceneToJson(scene))) {
            QVERIFY(!light.toObject().contains(QStringLiteral("name")));
            QVERIFY(!light.toObject().contains(QStringLiteral("enabled")));
        }
    }

    void disabledLightsCountTowardsTheLimit()
    {
        QByteArray nine = "[";
        for (int i = 0; i < kMaxLights + 1; ++i)
            nine += QByteArray(i ? ", " : "") + R"({"position": [1, 1, 1], "enabled": false})";
        const SceneLoadResult result = parseScene(withLights(nine + "]"));
        QVERIFY(!result.ok());
        QVERIFY2(result.error.startsWith(QStringLiteral("lights:")), qPrintable(result.error));
    }

    void rejectsBadTypes_data()
    {
        QTest::addColumn<QByteArray>("lights");
        QTest::addColumn<QString>("error");
        QTest::newRow("enabled number")
            << QByteArray(R"([{"position": [1, 1, 1]}, {"position": [1, 1, 1], "enabled": 0}])")
            << QStringLiteral("lights[1].enabled: expected true or false (got number)");
        QTest::newRow("enabled string")
            << QByteArray(R"([{"position": [1, 1, 1], "enabled": "false"}])")
            << QStringLiteral("lights[0].enabled: expected true or false (got string)");
        QTest::newRow("enabled null")
            << QByteArray(R"([{"position": [1, 1, 1], "enabled": null}])")
            << QStringLiteral("lights[0].enabled: expected true or false (got null)");
        QTest::newRow("name number")
            << QByteArray(R"([{"position": [1, 1, 1], "name": 3}])")
            << QStringLiteral("lights[0].name: expected a string (got number)");
        QTest::newRow("name array")
            << QByteArray(R"([{"position": [1, 1, 1]}, {"position": [1, 1, 1], "name": ["a"]}])")
            << QStringLiteral("lights[1].name: expected a string (got array)");
    }

    void rejectsBadTypes()
    {
        QFETCH(QByteArray, lights);
        QFETCH(QString, error);
        const SceneLoadResult result = parseScene(withLights(lights));
        QVERIFY(!result.ok());
        QCOMPARE(result.error, error);
    }
};

QTEST_GUILESS_MAIN(TestSceneLights)
#include "tst_scenelights.moc"
