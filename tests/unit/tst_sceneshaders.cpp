// The optional top-level "shaders" key of a scene file: shader files that
// replace the shading method's shipped ones.
#include "core/scene/SceneJson.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace phonglab;

namespace {

// A scene object of `mesh`, the rest as a new object has it.
SceneObject objectOf(const QString &mesh)
{
    SceneObject object;
    object.mesh = mesh;
    return object;
}

QByteArray sceneWith(const QByteArray &shadersJson)
{
    return R"({"mesh": "builtin:sphere", "shaders": )" + shadersJson + "}";
}

} // namespace

class TestSceneShaders : public QObject
{
    Q_OBJECT

private slots:
    void absentMeansShipped()
    {
        const SceneLoadResult loaded = parseScene(R"({"mesh": "builtin:sphere"})");
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        QVERIFY(loaded.scene->vertexShader.isEmpty());
        QVERIFY(loaded.scene->fragmentShader.isEmpty());
        // Not written when not set.
        QVERIFY(!sceneToJson(*loaded.scene).contains("\"shaders\""));
    }

    void bothKeysRead()
    {
        const SceneLoadResult loaded = parseScene(
            sceneWith(R"({"vertex": "glsl/a.vert", "fragment": "/abs/b.frag"})"), "/scenes");
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        QCOMPARE(loaded.scene->vertexShader, QStringLiteral("glsl/a.vert"));
        QCOMPARE(loaded.scene->fragmentShader, QStringLiteral("/abs/b.frag"));
        QVERIFY(loaded.warnings.isEmpty());
    }

    void eitherKeyOptional()
    {
        const SceneLoadResult loaded = parseScene(sceneWith(R"({"fragment": "b.frag"})"));
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        QVERIFY(loaded.scene->vertexShader.isEmpty());
        QCOMPARE(loaded.scene->fragmentShader, QStringLiteral("b.frag"));
        const QByteArray json = sceneToJson(*loaded.scene);
        QVERIFY(json.contains("\"fragment\""));
        QVERIFY(!json.contains("\"vertex\""));
    }

    void roundTrip()
    {
        Scene scene;
        scene.objects = {objectOf(QStringLiteral("builtin:torus"))};
        scene.vertexShader = QStringLiteral("shaders/my.vert");
        scene.fragmentShader = QStringLiteral("../elsewhere/my.frag");
        const SceneLoadResult back = parseScene(sceneToJson(scene));
        QVERIFY2(back.ok(), qPrintable(back.error));
        QCOMPARE(back.scene->vertexShader, scene.vertexShader);
        QCOMPARE(back.scene->fragmentShader, scene.fragmentShader);
        QVERIFY(*back.scene == scene);

        // Also through a file, which must keep the paths exactly as written.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("s.json"));
        const Result<> saved = saveSceneFile(scene, path);
        QVERIFY2(saved, qPrintable(saved.error()));
        const SceneLoadResult file = loadSceneFile(path);
        QVERIFY2(file.ok(), qPrintable(file.error));
        QCOMPARE(file.scene->vertexShader, scene.vertexShader);
        QCOMPARE(file.scene->fragmentShader, scene.fragmentShader);
    }

    void differentShadersCompareUnequal()
    {
        Scene a;
        a.objects = {objectOf(QStringLiteral("builtin:sphere"))};
        Scene b = a;
        b.fragmentShader = QStringLiteral("x.frag");
        QVERIFY(!(a == b));
    }

    void relativeResolution()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("scenes")));
        const QString path = dir.filePath(QStringLiteral("scenes/s.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(sceneWith(R"({"vertex": "glsl/a.vert", "fragment": "../b.frag"})"));
        file.close();
        const SceneLoadResult loaded = loadSceneFile(path);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        const QDir scenes(dir.filePath(QStringLiteral("scenes")));
        QCOMPARE(loaded.scene->resolveShaderPath(loaded.scene->vertexShader),
                 QDir::cleanPath(scenes.absoluteFilePath(QStringLiteral("glsl/a.vert"))));
        QCOMPARE(loaded.scene->resolveShaderPath(loaded.scene->fragmentShader),
                 QDir::cleanPath(dir.filePath(QStringLiteral("b.frag"))));
        // Absolute paths and empty (= shipped) are used as they are.
        QCOMPARE(loaded.scene->resolveShaderPath(QStringLiteral("/x/y.frag")),
                 QStringLiteral("/x/y.frag"));
        QCOMPARE(loaded.scene->resolveShaderPath(QString()), QString());
    }

    void badTypes_data()
    {
        QTest::addColumn<QByteArray>("shaders");
        QTest::addColumn<QString>("error");
        QTest::newRow("string") << QByteArray(R"("a.frag")")
                                << QStringLiteral("shaders: expected an object");
        QTest::newRow("array") << QByteArray(R"(["a.vert"])")
                               << QStringLiteral("shaders: expected an object");
        QTest::newRow("null") << QByteArray("null")
                              << QStringLiteral("shaders: expected an object");
        QTest::newRow("vertex number") << QByteArray(R"({"vertex": 3})")
                                       << QStringLiteral("shaders.vertex: expected a string");
        QTest::newRow("fragment object") << QByteArray(R"({"fragment": {}})")
                                         << QStringLiteral("shaders.fragment: expected a string");
        QTest::newRow("fragment null") << QByteArray(R"({"fragment": null})")
                                       << QStringLiteral("shaders.fragment: expected a string");
        QTest::newRow("vertex empty") << QByteArray(R"({"vertex": ""})")
                                      << QStringLiteral("shaders.vertex: must not be empty");
        QTest::newRow("fragment empty") << QByteArray(R"({"vertex": "a.vert", "fragment": ""})")
                                        << QStringLiteral("shaders.fragment: must not be empty");
    }

    void badTypes()
    {
        QFETCH(QByteArray, shaders);
        QFETCH(QString, error);
        const SceneLoadResult loaded = parseScene(sceneWith(shaders));
        QVERIFY(!loaded.ok());
        QVERIFY2(loaded.error.startsWith(error), qPrintable(loaded.error));
    }

    void unknownKeyWarns()
    {
        const SceneLoadResult loaded = parseScene(sceneWith(R"({"geometry": "g.glsl"})"));
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        QCOMPARE(loaded.warnings,
                 QStringList{QStringLiteral("shaders.geometry: unknown key, ignored")});
    }
};

QTEST_GUILESS_MAIN(TestSceneShaders)
#include "tst_sceneshaders.moc"
