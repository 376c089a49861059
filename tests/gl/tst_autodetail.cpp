// "detail": "auto" on the GPU: the renderer draws each auto object at the
// level its projected error allows (coarser far away, the full mesh up
// close), the level moves with the camera without flickering, and flat
// shading draws from the level's own face layout.
#include "RenderCheck.h"
#include "core/reference/ImageMetrics.h"
#include "core/view/DetailSelection.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/GlFormat.h"
#include "render/gl/QtImages.h"

#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

// The geometric rule alone: any normal deviation allowed.
void allowAnyShading(Renderer &renderer)
{
    Renderer::Options options = renderer.options();
    options.detailShadingAllowance = std::numeric_limits<double>::infinity();
    renderer.setOptions(options);
}

Scene autoSphere(double distance)
{
    Scene scene = loadTestScene(QStringLiteral("gl_sphere_one_light"));
    scene.objects.front().autoDetail = true;
    scene.camera.eye = {0, 0, distance};
    return scene;
}

} // namespace

class TestAutoDetail : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0)); }

    void levelFollowsTheView()
    {
        OffscreenRenderer offscreen;
        QVERIFY(offscreen.create());
        Renderer &renderer = offscreen.renderer();
        const auto set = renderer.setScene(autoSphere(4.0));
        QVERIFY2(set, qPrintable(set.error()));
        allowAnyShading(renderer);
        QVERIFY(renderer.loadShading(ShadingMethod::Phong).ok);
        const QSize size(kTestImageSide, kTestImageSide);

        std::vector<int> levels;
        std::vector<qint64> triangles;
        for (double distance : {4.0, 12.0, 40.0, 12.0, 4.0, 1.2}) {
            renderer.updateSceneParameters(autoSphere(distance));
            offscreen.renderImage(size);
            const Renderer::ObjectDraw drawn = renderer.objectDraws().front();
            QVERIFY(drawn.levels > 4);
            levels.push_back(drawn.level);
            triangles.push_back(drawn.triangles);
            QCOMPARE(renderer.trianglesDrawn(), drawn.triangles);
        }
        qInfo("levels at 4, 12, 40, 12, 4, 1.2 units: %d %d %d %d %d %d", levels[0], levels[1],
              levels[2], levels[3], levels[4], levels[5]);
        QVERIFY(levels[1] > levels[0]);
        QVERIFY(levels[2] > levels[1]);
        QVERIFY(triangles[2] <= triangles[0] / 8);
        // Coming back, the finer level is taken again; very close, the full mesh.
        QVERIFY(levels[3] <= levels[1]);
        QVERIFY(levels[4] <= levels[0]);
        QCOMPARE(levels[5], 0);
    }

    void autoDetailStaysCloseToTheFullMesh()
    {
        // Within half a pixel of geometric error, the picture barely changes.
        OffscreenRenderer offscreen;
        QVERIFY(offscreen.create());
        Renderer &renderer = offscreen.renderer();
        const QSize size(kTestImageSide, kTestImageSide);
        Scene full = autoSphere(12.0);
        full.objects.front().autoDetail = false;
        QVERIFY(renderer.setScene(full));
        QVERIFY(renderer.loadShading(ShadingMethod::Phong).ok);
        const RgbImage fullImage = toRgbImage(offscreen.renderImage(size));
        QVERIFY(renderer.setScene(autoSphere(12.0)));
        allowAnyShading(renderer);
        const RgbImage autoImage = toRgbImage(offscreen.renderImage(size));
        QVERIFY(renderer.objectDraws().front().level > 0);
        const ImageComparison diff = compareImages(autoImage, fullImage);
        qInfo("level %d against the full mesh: %s", renderer.objectDraws().front().level,
              qPrintable(diff.summary()));
        QVERIFY2(diff.psnr > 35.0, qPrintable(diff.summary()));
    }

    void shadingAllowanceKeepsShinyNormals();
    void flatDrawsTheLevelsOwnFaces()
    {
        OffscreenRenderer offscreen;
        QVERIFY(offscreen.create());
        Renderer &renderer = offscreen.renderer();
        QVERIFY(renderer.setScene(autoSphere(40.0)));
        allowAnyShading(renderer);
        QVERIFY(renderer.loadShading(ShadingMethod::Flat).ok);
        const QImage image = offscreen.renderImage(QSize(kTestImageSide, kTestImageSide));
        QVERIFY2(renderer.drawError().isEmpty(), qPrintable(renderer.drawError()));
        const Renderer::ObjectDraw drawn = renderer.objectDraws().front();
        QVERIFY(drawn.level > 0);
        // Something was drawn in the middle of the frame.
        QVERIFY(image.pixelColor(kTestImageSide / 2, kTestImageSide / 2) != image.pixelColor(0, 0));
    }
};

void TestAutoDetail::shadingAllowanceKeepsShinyNormals()
{
    // The default allowance (half an 8-bit step): the shiny sphere's
    // coarser levels bend its normals enough to move the highlight by more
    // (normalErrorBound), so it keeps the full mesh at any distance...
    OffscreenRenderer offscreen;
    QVERIFY(offscreen.create());
    Renderer &renderer = offscreen.renderer();
    QVERIFY(renderer.setScene(autoSphere(12.0)));
    QVERIFY(renderer.loadShading(ShadingMethod::Phong).ok);
    const QSize size(kTestImageSide, kTestImageSide);
    for (double distance : {4.0, 12.0, 40.0}) {
        renderer.updateSceneParameters(autoSphere(distance));
        offscreen.renderImage(size);
        QCOMPARE(renderer.objectDraws().front().level, 0);
    }
    // ... until it is a few pixels across, where it takes its coarsest.
    renderer.updateSceneParameters(autoSphere(400.0));
    offscreen.renderImage(size);
    QCOMPARE(renderer.objectDraws().front().level, renderer.objectDraws().front().levels - 1);
}

QTEST_MAIN(TestAutoDetail)
#include "tst_autodetail.moc"
