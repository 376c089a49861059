// The near/far planes a frame is drawn with: the camera's, moved inwards to
// what the scene occupies, never outwards.
#include "core/view/DepthRange.h"

#include <QTest>
#include <glm/gtc/matrix_transform.hpp>

using namespace phonglab;

class TestDepthRange : public QObject
{
    Q_OBJECT

private slots:
    void sphereAfterModelHoldsTheBox();
    void fitsTheSpheresInsideTheCameraRange();
    void neverWidensTheCameraRange();
    void eyeInsideKeepsTheCameraNear();
    void nothingInRangeOrNotFiniteKeepsTheCamera();
    void warnsOnlyWhenPrecisionIsLost();
};

namespace {

Camera extremeCamera()
{
    Camera c;
    c.eye = {0, 0, 10};
    c.target = {0, 0, 0};
    c.nearPlane = 1e-9;
    c.farPlane = 1e12;
    return c;
}

} // namespace

void TestDepthRange::sphereAfterModelHoldsTheBox()
{
    const glm::dmat4 model =
        glm::scale(glm::translate(glm::dmat4(1.0), {1, 2, 3}), {-2.0, 0.5, 1.0});
    const BoundingSphere s = boundingSphere({-1, -1, -1}, {1, 1, 1}, model);
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
        const glm::dvec3 p(model * glm::dvec4(corner, 1.0));
        QVERIFY(glm::length(p - s.center) <= s.radius + 1e-12);
    }
    QCOMPARE(s.center, glm::dvec3(1, 2, 3));
}

void TestDepthRange::fitsTheSpheresInsideTheCameraRange()
{
    const BoundingSphere spheres[] = {{{0, 0, 0}, 1.0}, {{0.5, 0, -3}, 0.5}};
    const DepthRange r = fitDepthRange(extremeCamera(), spheres);
    // Depths along the view: 9..11 and 12.5..13.5, with 0.1 % slack.
    QVERIFY(qAbs(r.nearPlane - 9.0 * 0.999) < 1e-12);
    QVERIFY(qAbs(r.farPlane - 13.5 * 1.001) < 1e-12);
    QVERIFY(r.ratio() < 2.0);
    QVERIFY(!depthPrecisionWarning(r));
}

void TestDepthRange::neverWidensTheCameraRange()
{
    Camera c = extremeCamera();
    c.nearPlane = 9.5;
    c.farPlane = 10.5;
    const BoundingSphere spheres[] = {{{0, 0, 0}, 1.0}};
    const DepthRange r = fitDepthRange(c, spheres);
    QCOMPARE(r.nearPlane, 9.5);
    QCOMPARE(r.farPlane, 10.5);
}

void TestDepthRange::eyeInsideKeepsTheCameraNear()
{
    const BoundingSphere spheres[] = {{{0, 0, 10}, 3.0}};
    const DepthRange r = fitDepthRange(extremeCamera(), spheres);
    QCOMPARE(r.nearPlane, 1e-9);
    QVERIFY(qAbs(r.farPlane - 3.0 * 1.001) < 1e-12);
    QVERIFY(depthPrecisionWarning(r).has_value());
    QVERIFY(depthPrecisionWarning(r)->contains(QLatin1String("raise near")));
}

void TestDepthRange::nothingInRangeOrNotFiniteKeepsTheCamera()
{
    const Camera c = extremeCamera();
    const BoundingSphere behind[] = {{{0, 0, 20}, 1.0}};
    QCOMPARE(fitDepthRange(c, behind).nearPlane, c.nearPlane);
    QCOMPARE(fitDepthRange(c, behind).farPlane, c.farPlane);
    const BoundingSphere broken[] = {{{0, 0, 0}, 1.0}, {{qQNaN(), 0, 0}, 1.0}};
    QCOMPARE(fitDepthRange(c, broken).farPlane, c.farPlane);
    QCOMPARE(fitDepthRange(c, {}).nearPlane, c.nearPlane);
}

void TestDepthRange::warnsOnlyWhenPrecisionIsLost()
{
    QVERIFY(!depthPrecisionWarning({0.1, 100.0}));
    QVERIFY(!depthPrecisionWarning({1e-3, 999.0}));
    QVERIFY(depthPrecisionWarning({1e-6, 10.0}).has_value());
}

QTEST_APPLESS_MAIN(TestDepthRange)
#include "tst_depthrange.moc"
