// A scene's camera moved back until every object is in a view of a given
// shape: only ever back along its line of sight, exactly as far as the
// point nearest an edge needs, and not at all when everything shows.
#include "core/view/CameraFraming.h"

#include <QTest>
#include <vector>

using namespace phonglab;

class TestCameraFraming : public QObject
{
    Q_OBJECT

private slots:
    void everythingInViewKeepsTheCamera();
    void narrowViewMovesTheEyeBackUntilAllShow();
    void onlyTheEyeMovesAndOnlyBack();
    void tallViewFitsTheHeight();
    void degenerateInputKeepsTheCamera();
};

namespace {

Camera frontCamera()
{
    Camera c;
    c.eye = {0, 0, 5};
    c.target = {0, 0, 0};
    c.fovDeg = 45.0;
    return c;
}

// Where `point` lands in normalised device coordinates for `camera` and `aspect`.
glm::dvec3 ndc(const Camera &camera, double aspect, const glm::dvec3 &point)
{
    const glm::dvec4 clip =
        camera.projectionMatrix(aspect) * camera.viewMatrix() * glm::dvec4(point, 1.0);
    return glm::dvec3(clip) / clip.w;
}

double largestNdc(const Camera &camera, double aspect, const std::vector<glm::dvec3> &points)
{
    double largest = 0.0;
    for (const glm::dvec3 &p : points) {
        const glm::dvec3 d = ndc(camera, aspect, p);
        largest = std::max({largest, std::abs(d.x), std::abs(d.y)});
    }
    return largest;
}

// Two boxes side by side, as the default scene's tree and cloud: wider than tall.
std::vector<glm::dvec3> sideBySide()
{
    std::vector<glm::dvec3> corners;
    for (double cx : {-1.6, 1.6})
        for (int i = 0; i < 8; ++i)
            corners.push_back({cx + (i & 1 ? 0.7 : -0.7), i & 2 ? 0.8 : -0.8, i & 4 ? 0.5 : -0.5});
    return corners;
}

} // namespace

void TestCameraFraming::everythingInViewKeepsTheCamera()
{
    const Camera camera = frontCamera();
    const std::vector<glm::dvec3> points = sideBySide();
    QVERIFY(largestNdc(camera, 2.0, points) < 0.9);      // a wide view shows both boxes
    QCOMPARE(framedCamera(camera, points, 2.0), camera); // exactly, not approximately
}

void TestCameraFraming::narrowViewMovesTheEyeBackUntilAllShow()
{
    const Camera camera = frontCamera();
    const std::vector<glm::dvec3> points = sideBySide();
    for (double aspect : {1.0, 0.8, 0.5}) {
        QVERIFY2(largestNdc(camera, aspect, points) > 1.0, "the boxes are cut off at first");
        const double margin = 0.05;
        const Camera framed = framedCamera(camera, points, aspect, margin);
        const double largest = largestNdc(framed, aspect, points);
        // Inside, with the margin to spare, and no further back than that needs.
        QVERIFY2(largest <= 1.0 - margin + 1e-9, qPrintable(QString::number(largest)));
        QVERIFY2(largest >= 1.0 - margin - 1e-9, qPrintable(QString::number(largest)));
    }
}

void TestCameraFraming::onlyTheEyeMovesAndOnlyBack()
{
    Camera camera = frontCamera();
    camera.eye = {3, 2, 4}; // an oblique view
    camera.up = {0, 1, 0};
    const std::vector<glm::dvec3> points = sideBySide();
    const Camera framed = framedCamera(camera, points, 0.6);
    QCOMPARE(framed.target, camera.target);
    QCOMPARE(framed.up, camera.up);
    QCOMPARE(framed.fovDeg, camera.fovDeg);
    QCOMPARE(framed.nearPlane, camera.nearPlane);
    QCOMPARE(framed.farPlane, camera.farPlane);
    const glm::dvec3 before = glm::normalize(camera.eye - camera.target);
    const glm::dvec3 after = glm::normalize(framed.eye - framed.target);
    QVERIFY(glm::length(after - before) < 1e-12); // the same line of sight
    QVERIFY(glm::length(framed.eye - framed.target) > glm::length(camera.eye - camera.target));
    QVERIFY(largestNdc(framed, 0.6, points) <= 1.0);
}

void TestCameraFraming::tallViewFitsTheHeight()
{
    const Camera camera = frontCamera();
    const std::vector<glm::dvec3> tower{{0, -3, 0}, {0, 3, 0}, {0.2, 0, 0}};
    const Camera framed = framedCamera(camera, tower, 3.0);
    const glm::dvec3 top = ndc(framed, 3.0, tower[1]);
    QVERIFY2(std::abs(top.y) > 0.9 && std::abs(top.y) <= 0.95 + 1e-9,
             qPrintable(QString::number(top.y)));
}

void TestCameraFraming::degenerateInputKeepsTheCamera()
{
    const Camera camera = frontCamera();
    const std::vector<glm::dvec3> points = sideBySide();
    QCOMPARE(framedCamera(camera, {}, 0.5), camera);
    QCOMPARE(framedCamera(camera, points, 0.0), camera);
    QCOMPARE(framedCamera(camera, points, std::nan("")), camera);
    Camera onTarget = camera;
    onTarget.eye = onTarget.target;
    QCOMPARE(framedCamera(onTarget, points, 0.5), onTarget);
    Camera alongUp = camera;
    alongUp.eye = {0, 5, 0};
    QCOMPARE(framedCamera(alongUp, points, 0.5), alongUp);
    const std::vector<glm::dvec3> far{{1e308, 0, 0}};
    const Camera framed = framedCamera(camera, far, 0.5);
    QVERIFY(std::isfinite(framed.eye.z));
}

QTEST_APPLESS_MAIN(TestCameraFraming)
#include "tst_cameraframing.moc"
