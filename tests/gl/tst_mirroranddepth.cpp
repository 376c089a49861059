// Two ways a correct shader used to give a wrong frame, against the
// double-precision reference: an object mirrored by its transform rendered
// inside out (its triangles wind the other way and back-face culling removed
// the front), and a camera with an extreme near/far range collapsed the
// depth buffer into an empty or scrambled frame.
#include "RenderCheck.h"
#include "core/view/DepthRange.h"
#include "render/gl/GlFormat.h"

#include <QGuiApplication>
#include <QTest>

Q_DECLARE_METATYPE(glm::dvec3)

using namespace phonglab;
using namespace phonglab::test;

class TestMirrorAndDepth : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void mirroredObjectMatchesReference_data();
    void mirroredObjectMatchesReference();
    void extremeDepthRangeMatchesReference_data();
    void extremeDepthRangeMatchesReference();

private:
    enum class Contours {
        Compared,
        LeftOut
    };
    static void verifyMatches(const QString &name, const Scene &scene,
                              Contours contours = Contours::Compared);
};

void TestMirrorAndDepth::initTestCase()
{
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
}

void TestMirrorAndDepth::verifyMatches(const QString &name, const Scene &scene, Contours contours)
{
    RenderCheck check = checkAgainstReference(scene);
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    if (contours == Contours::LeftOut) {
        // Where one object passes in front of another, the tessellated and
        // the true outline cover different pixels, as at the silhouette: the
        // same band is left out there.
        const ReferenceImage &ref = check.referenceData;
        std::vector<std::uint8_t> compared =
            dilatePixels(occludingContourPixels(ref), ref.width, ref.height, kSilhouetteBandPx);
        for (std::uint8_t &c : compared)
            c = !c;
        check.comparison =
            compareOutsideBand(check.gpu, ref, scene.background, kSilhouetteBandPx, &compared)
                .error;
    }
    qInfo("%-34s %s", qPrintable(name), qPrintable(check.comparison.summary()));
    QVERIFY2(check.comparison.pixelsCompared > kTestImageSide * kTestImageSide / 10,
             qPrintable(check.comparison.summary()));
    if (!check.matches())
        QFAIL(qPrintable(QStringLiteral("%1 (images in %2)")
                             .arg(check.comparison.summary(), saveArtifacts(name, check, scene))));
}

void TestMirrorAndDepth::mirroredObjectMatchesReference_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<glm::dvec3>("scale");
    // One or three negative components mirror (det < 0); two do not (a turn
    // by 180°), which must keep working as before.
    QTest::newRow("torus, x mirrored") << "gl_torus" << glm::dvec3(-1.6, 0.6, 1.0);
    QTest::newRow("torus, z mirrored") << "gl_torus" << glm::dvec3(1.0, 1.0, -1.0);
    QTest::newRow("torus, x and y mirrored") << "gl_torus" << glm::dvec3(-1.0, -1.3, 1.0);
    QTest::newRow("torus, all three mirrored") << "gl_torus" << glm::dvec3(-1.0, -1.0, -1.0);
    QTest::newRow("ellipsoid, y mirrored")
        << "gl_ellipsoid_nonuniform" << glm::dvec3(1.2, -0.7, 0.9);
    QTest::newRow("box, x mirrored") << "gl_cube" << glm::dvec3(-1.0, 0.8, 1.2);
}

void TestMirrorAndDepth::mirroredObjectMatchesReference()
{
    QFETCH(QString, scene);
    QFETCH(glm::dvec3, scale);
    Scene s = loadTestScene(scene);
    QVERIFY(!s.objects.empty());
    for (SceneObject &object : s.objects)
        object.transform.scale = scale;
    verifyMatches(
        QStringLiteral("%1, scale (%2, %3, %4)").arg(scene).arg(scale.x).arg(scale.y).arg(scale.z),
        s);
}

void TestMirrorAndDepth::extremeDepthRangeMatchesReference_data()
{
    QTest::addColumn<double>("nearPlane");
    QTest::addColumn<double>("farPlane");
    QTest::newRow("near 1e-6, far 1e9") << 1e-6 << 1e9;
    QTest::newRow("near 1e-9, far 1e12") << 1e-9 << 1e12;
    QTest::newRow("near 1e-3, far 1e15") << 1e-3 << 1e15;
}

void TestMirrorAndDepth::extremeDepthRangeMatchesReference()
{
    QFETCH(double, nearPlane);
    QFETCH(double, farPlane);
    // A torus with a sphere in front of it: the sphere hides part of the
    // torus, so only a working depth buffer gets the occlusion right (they
    // do not intersect: an intersection curve of two tessellated surfaces
    // is no more exact than an outline).
    Scene s = loadTestScene(QStringLiteral("gl_torus"));
    SceneObject sphere = s.objects.front();
    sphere.mesh = QStringLiteral("builtin:sphere");
    sphere.transform = {};
    sphere.transform.translate = {0.4, 0.1, 1.4};
    sphere.transform.scale = glm::dvec3(0.45);
    s.objects.push_back(sphere);
    s.camera.nearPlane = nearPlane;
    s.camera.farPlane = farPlane;
    verifyMatches(QStringLiteral("near %1, far %2").arg(nearPlane).arg(farPlane), s,
                  Contours::LeftOut);
}

QTEST_MAIN(TestMirrorAndDepth)
#include "tst_mirroranddepth.moc"
