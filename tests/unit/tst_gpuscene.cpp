// The viewport's scene as state, before any GL (GpuScene): meshes kept for
// the GL start and a missing one refused, the camera framed to the view
// until the user moves it (and what Save writes then), the headlight added
// only where a light is free, and dock edits that change parameters but not
// the objects.
#include "mesh/loading/SceneMeshes.h"
#include "render/draw/GpuScene.h"

#include <QTest>

using namespace phonglab;

namespace {

Scene twoSpheres()
{
    Scene scene;
    for (double x : {-1.0, 1.0}) {
        SceneObject object;
        object.mesh = QStringLiteral("builtin:sphere");
        object.transform.translate = {x, 0.0, 0.0};
        scene.objects.push_back(object);
    }
    scene.lights.push_back(PointLight{});
    scene.camera.eye = {0.0, 0.0, 1.0}; // too near to see both: framing moves it back
    return scene;
}

// A scene shown before GL, as the window shows its first one.
void showBeforeGl(GpuScene &gpu, const Scene &scene)
{
    QVERIFY(gpu.keepUntilInitialized(scene, loadSceneMeshes(scene)));
    gpu.show(scene);
}

} // namespace

class TestGpuScene : public QObject
{
    Q_OBJECT

private slots:
    void meshesWaitForGlAndAMissingOneIsRefused()
    {
        GpuScene gpu;
        const Scene scene = twoSpheres();
        showBeforeGl(gpu, scene);
        QVERIFY(!gpu.isInitialized());
        QVERIFY(!gpu.isReady());
        QCOMPARE(gpu.meshInfo().size(), 1);  // one sphere mesh, used twice
        QVERIFY(gpu.loadedKeys().isEmpty()); // nothing is on the GPU yet

        Scene other = scene;
        other.objects[1].mesh = QStringLiteral("builtin:cube");
        const Result<> kept = gpu.keepUntilInitialized(other, loadSceneMeshes(scene));
        QVERIFY(!kept);
        QVERIFY2(kept.error().contains(QStringLiteral("builtin:cube")), qPrintable(kept.error()));
        QVERIFY(kept.error().contains(QStringLiteral("was not loaded")));
    }

    void cameraFramedUntilTheUserMovesIt()
    {
        GpuScene gpu;
        const Scene scene = twoSpheres();
        showBeforeGl(gpu, scene);
        QVERIFY(gpu.frame({800, 600}));
        QVERIFY(gpu.isCameraFramed());
        QVERIFY(gpu.camera().eye.z > scene.camera.eye.z); // moved back to show both
        QCOMPARE(gpu.cameraToSave(), scene.camera);       // the scene's own, not the fitted one
        QVERIFY(gpu.currentScene().camera.frameObjects);
        QVERIFY(!gpu.frame({800, 600})); // the same view: nothing moves
        const Camera framed = gpu.camera();

        gpu.orbitByUser().orbit(30.0, 0.0);
        QVERIFY(!gpu.isCameraFramed());
        QCOMPARE(gpu.cameraToSave(), gpu.currentScene().camera); // the user's shot
        QVERIFY(!gpu.cameraToSave().frameObjects);
        QVERIFY(!(gpu.cameraToSave() == scene.camera));

        gpu.resetCamera(); // Reset Camera: back to the framed shot
        gpu.frame({800, 600});
        QVERIFY(gpu.isCameraFramed());
        QCOMPARE(gpu.camera(), framed);
        QVERIFY(gpu.frame({300, 900})); // a tall view needs the camera further back
        QVERIFY(gpu.camera().eye.z > framed.eye.z);
    }

    void headlightOnlyWhereALightIsFree()
    {
        GpuScene gpu;
        Scene scene = twoSpheres();
        showBeforeGl(gpu, scene);
        gpu.setHeadlight(true);
        const Scene rendered = gpu.renderedScene();
        QCOMPARE(rendered.lights.size(), scene.lights.size() + 1);
        QCOMPARE(rendered.lights.back().position, gpu.camera().eye);
        QCOMPARE(gpu.currentScene().lights.size(), scene.lights.size()); // not the scene's

        scene.lights.assign(kMaxLights, PointLight{});
        gpu.setParameters(scene);
        QCOMPARE(gpu.renderedScene().lights.size(), std::size_t(kMaxLights));
        scene.lights.back().enabled = false; // a disabled light leaves room
        gpu.setParameters(scene);
        QCOMPARE(gpu.renderedScene().lights.size(), std::size_t(kMaxLights + 1));
    }

    void parametersChangeButObjectsStay()
    {
        GpuScene gpu;
        const Scene scene = twoSpheres();
        showBeforeGl(gpu, scene);
        Scene edited = scene;
        edited.objects[0].material.shininess = 77.0;
        edited.objects[1].transform.translate = {0.0, 2.0, 0.0};
        edited.objects.push_back(edited.objects[0]); // a third: not ours to add here
        edited.objects[0].mesh = QStringLiteral("builtin:cube");
        edited.lights[0].position = {1.0, 2.0, 3.0};
        gpu.setParameters(edited);
        const Scene &shown = gpu.scene();
        QCOMPARE(shown.objects.size(), std::size_t(2));
        QCOMPARE(shown.objects[0].mesh, QStringLiteral("builtin:sphere"));
        QCOMPARE(shown.objects[0].material.shininess, 77.0);
        QCOMPARE(shown.objects[1].transform.translate, glm::dvec3(0.0, 2.0, 0.0));
        QCOMPARE(shown.lights[0].position, glm::dvec3(1.0, 2.0, 3.0));

        gpu.moveLight(0, {4.0, 5.0, 6.0});
        QCOMPARE(gpu.scene().lights[0].position, glm::dvec3(4.0, 5.0, 6.0));
    }
};

QTEST_GUILESS_MAIN(TestGpuScene)
#include "tst_gpuscene.moc"
