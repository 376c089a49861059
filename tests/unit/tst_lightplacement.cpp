// The lights are seen in the first view, and a new one lands
// where it is seen (Add Light put it outside the course scene's view).
#include "TestPaths.h"
#include "core/scene/SceneJson.h"
#include "core/view/LightPlacement.h"

#include <QtTest>

using namespace phonglab;

class TestLightPlacement : public QObject
{
    Q_OBJECT

private slots:
    void newLightsLandInView_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::newRow("default") << QStringLiteral("assets/scenes/default.json");
        QTest::newRow("course") << QStringLiteral("tests/data/course/scene.json");
        QTest::newRow("check") << QStringLiteral("assets/scenes/check.json");
    }
    void newLightsLandInView()
    {
        QFETCH(QString, scene);
        const SceneLoadResult loaded = loadSceneFile(test::sourcePath(scene));
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        const Camera &camera = loaded.scene->camera;
        // Portrait to wide: the window's view takes any shape.
        for (double aspect : {0.7, 1.0, 1.8})
            for (int index : {0, 1, 2}) {
                const glm::dvec3 p = visibleLightPosition(camera, index);
                QVERIFY2(
                    isInView(camera, aspect, p, 0.2),
                    qPrintable(QStringLiteral("light %1 at aspect %2").arg(index).arg(aspect)));
            }
        // The old placement, target + (2, 3, 2), was out of the course's view.
        if (scene.contains(QStringLiteral("course")))
            QVERIFY(!isInView(camera, 1.0, camera.target + glm::dvec3(2.0, 3.0, 2.0)));
        QVERIFY(visibleLightPosition(camera, 0) != visibleLightPosition(camera, 1));
    }

    // "The small spheres are the lights": both of the first launch's are in
    // its view, whatever the window's shape.
    void theDefaultScenesLightsAreInTheFirstView()
    {
        const SceneLoadResult loaded =
            loadSceneFile(test::sourcePath(QStringLiteral("assets/scenes/default.json")));
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        for (const PointLight &light : loaded.scene->lights)
            for (double aspect : {1.0, 1.2, 1.8})
                QVERIFY2(isInView(loaded.scene->camera, aspect, light.position, 0.05),
                         qPrintable(QStringLiteral("(%1, %2, %3) at aspect %4")
                                        .arg(light.position.x)
                                        .arg(light.position.y)
                                        .arg(light.position.z)
                                        .arg(aspect)));
    }
};

QTEST_APPLESS_MAIN(TestLightPlacement)
#include "tst_lightplacement.moc"
