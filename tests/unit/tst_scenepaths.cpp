// How a saved scene names its files (core/scene/ScenePaths): relative to the scene
// file's folder when under it, else absolute; meshes keep pointing at the
// same files when the scene is saved elsewhere.
#include "core/scene/ScenePaths.h"

#include <QDir>
#include <QTest>

using namespace phonglab;

class TestScenePaths : public QObject
{
    Q_OBJECT

private slots:
    void embeddedScenesAreNotWritable();
    void pathFromSceneIsRelativeOnlyUnderItsFolder();
    void rebasingKeepsMeshesInPlace();
};

void TestScenePaths::embeddedScenesAreNotWritable()
{
    QVERIFY(isWritableLocation(QStringLiteral("/home/a/scene.json")));
    QVERIFY(!isWritableLocation(QStringLiteral(":/assets/scenes/default.json")));
    QVERIFY(!isWritableLocation(QString()));
}

void TestScenePaths::pathFromSceneIsRelativeOnlyUnderItsFolder()
{
    const QString scene = QStringLiteral("/work/scenes/lab.json");
    QCOMPARE(pathFromScene(QStringLiteral("/work/scenes/shaders/my.frag"), scene),
             QStringLiteral("shaders/my.frag"));
    QCOMPARE(pathFromScene(QStringLiteral("/work/scenes/my.vert"), scene),
             QStringLiteral("my.vert"));
    QCOMPARE(pathFromScene(QStringLiteral("/work/other/my.frag"), scene),
             QStringLiteral("/work/other/my.frag"));
}

void TestScenePaths::rebasingKeepsMeshesInPlace()
{
    Scene scene;
    scene.baseDir = QStringLiteral("/work/scenes");
    SceneObject relative;
    relative.mesh = QStringLiteral("../meshes/tree.obj");
    SceneObject builtin;
    builtin.mesh = QStringLiteral("builtin:sphere");
    SceneObject absolute;
    absolute.mesh = QStringLiteral("/data/cloud.obj");
    SceneObject embedded;
    embedded.mesh = QStringLiteral("../meshes/cloud.obj");
    scene.objects = {relative, builtin, absolute};

    const Scene moved = rebasedOnto(scene, QStringLiteral("/work/saved/deeper/lab.json"));
    QCOMPARE(moved.baseDir, QStringLiteral("/work/saved/deeper"));
    QCOMPARE(moved.objects[0].mesh, QStringLiteral("../../meshes/tree.obj"));
    QCOMPARE(moved.resolveMeshPath(moved.objects[0].mesh), QStringLiteral("/work/meshes/tree.obj"));
    QCOMPARE(moved.objects[1].mesh, QStringLiteral("builtin:sphere"));
    QCOMPARE(moved.objects[2].mesh, QStringLiteral("/data/cloud.obj"));

    // A scene opened from the binary's resources: its meshes stay as named
    // (a resource path cannot be made relative to a folder on disk).
    Scene shipped;
    shipped.baseDir = QStringLiteral(":/assets/scenes");
    shipped.objects = {embedded};
    QCOMPARE(rebasedOnto(shipped, QStringLiteral("/work/lab.json")).objects[0].mesh,
             QStringLiteral("../meshes/cloud.obj"));
}

QTEST_APPLESS_MAIN(TestScenePaths)
#include "tst_scenepaths.moc"
