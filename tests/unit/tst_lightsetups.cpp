// The light setups of the bench (1, 4, 8 lights, and the scene's own) and the
// frame-timing statistics: pure functions, no GL.

#include "bench/LightSetups.h"
#include "render/draw/FrameTiming.h"

#include <QtTest>

using namespace phonglab;

namespace {

Scene twoLightScene()
{
    Scene scene;
    scene.camera.eye = {0, 1, 5};
    PointLight warm;
    warm.position = {-2, 2, 2};
    warm.diffuse = {1.0, 0.5, 0.25};
    warm.specular = {0.8, 0.8, 0.8};
    warm.attenuation = {1, 0.1, 0.01};
    PointLight cool = warm;
    cool.position = {2, 1, 2};
    cool.diffuse = {0.2, 0.4, 1.0};
    PointLight off = warm;
    off.enabled = false;
    scene.lights = {warm, off, cool};
    return scene;
}

} // namespace

class TestLightSetups : public QObject
{
    Q_OBJECT

private slots:
    void sceneCountIsTheScenesOwnLights()
    {
        const Scene scene = twoLightScene();
        QCOMPARE(scene.enabledLightCount(), 2);
        const std::vector<PointLight> lights = lightsForCount(scene, 2);
        QCOMPARE(lights.size(), std::size_t(2));
        QCOMPARE(lights[0], scene.lights[0]);
        QCOMPARE(lights[1], scene.lights[2]); // the disabled one is skipped
    }

    void fewerLightsTakeTheFirstUnscaled()
    {
        const Scene scene = twoLightScene();
        const std::vector<PointLight> one = lightsForCount(scene, 1);
        QCOMPARE(one.size(), std::size_t(1));
        QCOMPARE(one[0], scene.lights[0]);
    }

    void moreLightsKeepTheTotalAndFaceTheCamera()
    {
        const Scene scene = twoLightScene();
        for (int count : {4, 8}) {
            const std::vector<PointLight> lights = lightsForCount(scene, count);
            QCOMPARE(int(lights.size()), count);
            glm::dvec3 total(0.0);
            for (const PointLight &l : lights) {
                total += l.diffuse;
                QVERIFY(l.enabled);
                QCOMPARE(l.attenuation, scene.lights[0].attenuation);
                // On the camera's side of the target, so each one lights what is seen.
                QVERIFY(glm::dot(l.position - scene.camera.target,
                                 scene.camera.eye - scene.camera.target)
                        > 0.0);
            }
            const glm::dvec3 own = scene.lights[0].diffuse + scene.lights[2].diffuse;
            // Every light is scaled by 2/count; the generated ones repeat the
            // scene's colours in turn, so the sum equals the scene's own.
            QVERIFY(glm::length(total - own) < 1e-12);
            for (std::size_t i = 0; i < lights.size(); ++i)
                for (std::size_t j = i + 1; j < lights.size(); ++j)
                    QVERIFY(glm::length(lights[i].position - lights[j].position) > 0.1);
        }
    }

    void noSceneLightsStillGivesWhiteLights()
    {
        Scene scene;
        const std::vector<PointLight> lights = lightsForCount(scene, 4);
        QCOMPARE(lights.size(), std::size_t(4));
        QCOMPARE(lights[0].diffuse, glm::dvec3(1.0));
        QCOMPARE(lightsForCount(scene, 99).size(), std::size_t(kMaxLights));
        QVERIFY(lightsForCount(scene, -3).empty());
    }

    void statistics()
    {
        QCOMPARE(medianOf({3, 1, 2}), 2.0);
        QCOMPARE(medianOf({4, 1, 3, 2}), 2.5);
        QVERIFY(std::isnan(medianOf({})));
        std::vector<double> ramp;
        for (int i = 1; i <= 20; ++i)
            ramp.push_back(i);
        QCOMPARE(percentileOf(ramp, 0.9), 18.0); // nearest rank of 0.9·19 = 17.1 -> index 17
        QCOMPARE(percentileOf(ramp, 0.0), 1.0);
        QCOMPARE(percentileOf(ramp, 1.0), 20.0);
    }

    void timerQueriesAreDistrustedOnSoftwareRenderers()
    {
        QVERIFY(!timerQueryTrusted(QStringLiteral("llvmpipe (LLVM 15.0.6, 256 bits)")));
        QVERIFY(!timerQueryTrusted(QStringLiteral("softpipe")));
        QVERIFY(timerQueryTrusted(QStringLiteral("NVIDIA H100 80GB HBM3/PCIe/SSE2")));
    }
};

QTEST_APPLESS_MAIN(TestLightSetups)
#include "tst_lightsetups.moc"
