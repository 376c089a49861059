// Lights left out of an object's draw because they cannot be seen
// (Renderer::Options::lightAllowance, LightBound.h): the frame with them
// left out differs from the frame with every light by no more than the
// allowance, in 8-bit steps, and the same comparison fails when a light
// that is seen is dropped (an allowance far above the bound's).
#include "RenderCheck.h"
#include "core/reference/ImageMetrics.h"
#include "core/reference/LightBound.h"
#include "mesh/loading/SceneMeshes.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/GlFormat.h"
#include "render/gl/QtImages.h"

#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

constexpr int kAllowanceSteps = 2;

// The sphere test scene with its key light, a nearby fill light, and four
// far, strongly attenuated lights whose bounds sum to about 1.3 steps.
Scene litSphere()
{
    Scene scene = loadTestScene(QStringLiteral("gl_sphere_one_light"));
    PointLight fill;
    fill.position = {-6, 2, 3};
    fill.attenuation = {1, 0, 0.1};
    scene.lights.push_back(fill);
    for (const glm::dvec3 &p : {glm::dvec3(50, 0, 0), glm::dvec3(-50, 0, 0), glm::dvec3(0, 50, 0),
                                glm::dvec3(0, 0, 50)}) {
        PointLight far;
        far.position = p;
        far.attenuation = {1, 0, 0.5};
        scene.lights.push_back(far);
    }
    return scene;
}

struct Frames {
    RgbImage everyLight;
    RgbImage culled;
    int leftOut = 0;
    double leftOutBound = 0.0;
    QString error;
};

Frames renderBoth(const Scene &scene, double allowance)
{
    Frames out;
    OffscreenRenderer offscreen;
    if (const Result<> done = offscreen.create(); !done) {
        out.error = done.error();
        return out;
    }
    Renderer &renderer = offscreen.renderer();
    if (const Result<> done = renderer.setScene(scene); !done) {
        out.error = done.error();
        return out;
    }
    if (const BuildReport built = renderer.loadShading(ShadingMethod::Phong); !built.ok) {
        out.error = built.errorSummary();
        return out;
    }
    const QSize size(kTestImageSide, kTestImageSide);
    out.everyLight = toRgbImage(offscreen.renderImage(size));
    Renderer::Options options = renderer.options();
    options.lightAllowance = allowance;
    renderer.setOptions(options);
    out.culled = toRgbImage(offscreen.renderImage(size));
    out.leftOut = renderer.lightsLeftOut();
    out.leftOutBound = renderer.leftOutBound();
    return out;
}

} // namespace

class TestLightCulling : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0)); }

    void leftOutLightsStayWithinTheAllowance()
    {
        const Frames frames = renderBoth(litSphere(), kAllowanceSteps / 255.0);
        QVERIFY2(frames.error.isEmpty(), qPrintable(frames.error));
        const ImageComparison diff = compareImages(frames.culled, frames.everyLight);
        qInfo("%d lights left out, bound %.2f steps: %s", frames.leftOut,
              frames.leftOutBound * 255.0, qPrintable(diff.summary()));
        QCOMPARE(frames.leftOut, 4); // the far ones; the key and fill lights stay
        QVERIFY(frames.leftOutBound * 255.0 < kAllowanceSteps);
        QVERIFY2(diff.maxError <= kAllowanceSteps, qPrintable(diff.summary()));
    }

    void droppingASeenLightFails()
    {
        // The same comparison with an allowance that lets the fill light go.
        const Frames frames = renderBoth(litSphere(), 0.5);
        QVERIFY2(frames.error.isEmpty(), qPrintable(frames.error));
        const ImageComparison diff = compareImages(frames.culled, frames.everyLight);
        qInfo("WRONG: %d lights left out: %s", frames.leftOut, qPrintable(diff.summary()));
        QVERIFY(frames.leftOut > 4);
        QVERIFY2(diff.maxError > kAllowanceSteps, qPrintable(diff.summary()));
    }
};

QTEST_MAIN(TestLightCulling)
#include "tst_lightculling.moc"
