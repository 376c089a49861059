// GPU render versus the double-precision CPU reference (ray-cast analytic
// surfaces). Prints the figures per scene; deliberately wrong shaders must fail
// the very same comparison.
#include "RenderCheck.h"
#include "render/gl/GlFormat.h"

#include <QGuiApplication>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

class TestRenderReference : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void matchesReference_data();
    void matchesReference();
    void wrongVariantsFail_data();
    void wrongVariantsFail();
    void lightStaysInWorldWhileCameraOrbits();

private:
    void report(const QString &name, const RenderCheck &check);
};

void TestRenderReference::initTestCase()
{
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
    qInfo("bounds: PSNR >= %.1f dB, max error <= %d/255, outside a %d px silhouette band, %dx%d px",
          kMinPsnrDb, kMaxErrorSteps, kSilhouetteBandPx, kTestImageSide, kTestImageSide);
}

void TestRenderReference::report(const QString &name, const RenderCheck &check)
{
    qInfo("%-28s %s", qPrintable(name), qPrintable(check.comparison.summary()));
}

void TestRenderReference::matchesReference_data()
{
    QTest::addColumn<QString>("scene");
    QTest::newRow("sphere, one light") << "gl_sphere_one_light";
    QTest::newRow("ellipsoid, non-uniform scale") << "gl_ellipsoid_nonuniform";
    QTest::newRow("sphere, attenuated lights") << "gl_sphere_attenuated";
    QTest::newRow("torus, two lights") << "gl_torus";
    QTest::newRow("box, flat faces, non-uniform scale") << "gl_cube";
}

void TestRenderReference::matchesReference()
{
    QFETCH(QString, scene);
    const Scene s = loadTestScene(scene);
    const RenderCheck check = checkAgainstReference(s);
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    report(scene, check);
    // A render that compared almost nothing proves nothing.
    QVERIFY2(check.comparison.pixelsCompared > kTestImageSide * kTestImageSide / 10,
             qPrintable(check.comparison.summary()));
    if (!check.matches())
        QFAIL(qPrintable(QStringLiteral("%1 (images in %2)")
                             .arg(check.comparison.summary(), saveArtifacts(scene, check, s))));
}

void TestRenderReference::wrongVariantsFail_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QString>("vertex");   // empty: the shipped one
    QTest::addColumn<QString>("fragment"); // empty: the shipped one
    QTest::newRow("normals by model-view (non-uniform scale)")
        << "gl_ellipsoid_nonuniform"
        << "shaders/wrong_normal_modelview.vert"
        << "";
    QTest::newRow("direction with w = 1") << "gl_sphere_one_light"
                                          << ""
                                          << "shaders/wrong_direction_w1.frag";
    QTest::newRow("direction with w = 1, ellipsoid") << "gl_ellipsoid_nonuniform"
                                                     << ""
                                                     << "shaders/wrong_direction_w1.frag";
    QTest::newRow("lights left in world space") << "gl_sphere_attenuated"
                                                << ""
                                                << "shaders/wrong_light_not_viewed.frag";
}

void TestRenderReference::wrongVariantsFail()
{
    QFETCH(QString, scene);
    QFETCH(QString, vertex);
    QFETCH(QString, fragment);
    const Scene s = loadTestScene(scene);
    std::optional<ShaderSource> vs, fs;
    if (!vertex.isEmpty())
        vs = testShader(vertex);
    if (!fragment.isEmpty())
        fs = testShader(fragment);
    const RenderCheck check = checkAgainstReference(s, vs, fs);
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    report(QStringLiteral("WRONG ") + (vertex.isEmpty() ? fragment : vertex).section('/', -1),
           check);
    QVERIFY2(check.comparison.pixelsCompared > 0, "nothing compared");
    QVERIFY2(!check.matches(),
             qPrintable(QStringLiteral("a wrong shader passed: ") + check.comparison.summary()));
}

void TestRenderReference::lightStaysInWorldWhileCameraOrbits()
{
    Scene s = loadTestScene(QStringLiteral("gl_sphere_one_light"));
    // Two cameras on a circle around the sphere; the light must stay where
    // the world puts it, so each view matches its own reference.
    const double radius = glm::length(s.camera.eye - s.camera.target);
    RgbImage previous;
    for (double angleDeg : {0.0, 70.0}) {
        const double a = glm::radians(angleDeg);
        s.camera.eye = s.camera.target + radius * glm::dvec3(std::sin(a), 0.2, std::cos(a));
        const RenderCheck check = checkAgainstReference(s);
        QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
        report(QStringLiteral("orbit %1 deg").arg(angleDeg), check);
        QVERIFY2(check.matches(), qPrintable(check.comparison.summary()));
        if (!previous.isNull())
            QVERIFY2(check.gpu != previous, "the camera moved but the frame did not change");
        previous = check.gpu;

        // The same view with lights kept in world coordinates as if they were
        // camera coordinates (a light that follows the camera) must not match.
        const RenderCheck wrong = checkAgainstReference(
            s, std::nullopt, testShader(QStringLiteral("shaders/wrong_light_not_viewed.frag")));
        QVERIFY2(!wrong.matches(), qPrintable(wrong.comparison.summary()));
    }
}

QTEST_MAIN(TestRenderReference)
#include "tst_renderreference.moc"
