// Camera paths for `phonglab bench --path` (CameraPath.h): the orbit turns
// once while moving out, the dolly runs from just outside the scene to far
// away, and keyframe files are read with every error located.

#include "core/view/CameraPath.h"

#include <QtTest>

using namespace phonglab;

namespace {

Camera startCamera()
{
    Camera c;
    c.eye = {0, 0, 4};
    c.target = {0, 0, 0};
    return c;
}

} // namespace

class TestCameraPath : public QObject
{
    Q_OBJECT

private slots:
    void orbitTurnsOnceMovingOut()
    {
        const CameraPath path = orbitPath(startCamera(), 9);
        QCOMPARE(path.name, QStringLiteral("orbit"));
        QCOMPARE(path.cameras.size(), std::size_t(9));
        QCOMPARE(path.cameras.front().eye, glm::dvec3(0, 0, 4));
        QVERIFY(glm::length(path.cameras.back().eye - glm::dvec3(0, 0, 10)) < 1e-9);
        // Half way: the far side, at 1.75 times the distance.
        QVERIFY(glm::length(path.cameras[4].eye - glm::dvec3(0, 0, -7)) < 1e-9);
        for (const Camera &c : path.cameras)
            QCOMPARE(c.target, glm::dvec3(0.0));
    }

    void dollyRunsFromOutsideTheSceneToFarAway()
    {
        const CameraPath path = dollyPath(startCamera(), {{0, 0, 0}, 1.0}, 5);
        QCOMPARE(path.cameras.size(), std::size_t(5));
        QCOMPARE(path.cameras.front().eye.z, 1.25);
        QVERIFY(std::abs(path.cameras.back().eye.z - 128.0) < 1e-9);
        for (std::size_t i = 1; i < path.cameras.size(); ++i) {
            // Evenly spaced in the logarithm of the distance.
            QVERIFY(std::abs(path.cameras[i].eye.z / path.cameras[i - 1].eye.z
                             - std::pow(128.0 / 1.25, 0.25))
                    < 1e-9);
            QVERIFY(path.cameras[i].farPlane > path.cameras[i].eye.z + 1.0);
        }
    }

    void keyframesInterpolate()
    {
        const Result<CameraPath> path = parseCameraPath(R"({"frames": 5, "keyframes": [
            {"eye": [0, 0, 4]}, {"eye": [4, 0, 4], "fov_deg": 60}, {"eye": [4, 4, 4]}]})",
                                                        startCamera(), QStringLiteral("mine"));
        QVERIFY2(path, qPrintable(path.error()));
        QCOMPARE(path->name, QStringLiteral("mine"));
        QCOMPARE(path->cameras.size(), std::size_t(5));
        QCOMPARE(path->cameras[1].eye, glm::dvec3(2, 0, 4));
        QCOMPARE(path->cameras[1].fovDeg, 52.5);
        QCOMPARE(path->cameras[2].eye, glm::dvec3(4, 0, 4));
        QCOMPARE(path->cameras[3].eye, glm::dvec3(4, 2, 4));
        QCOMPARE(path->cameras[4].eye, glm::dvec3(4, 4, 4));
        QCOMPARE(path->cameras[4].fovDeg, 60.0); // carried from the keyframe before
    }

    void badKeyframesAreLocated_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("error");
        QTest::newRow("syntax") << QByteArray("{") << "JSON syntax error";
        QTest::newRow("array") << QByteArray("[]") << "top level:";
        QTest::newRow("one keyframe") << QByteArray(R"({"keyframes": [{"eye": [1, 2, 3]}]})")
                                      << "keyframes: expected an array of at least 2";
        QTest::newRow("frames") << QByteArray(R"({"frames": 1, "keyframes": []})") << "frames:";
        QTest::newRow("no eye") << QByteArray(R"({"keyframes": [{"eye": [0, 0, 4]}, {}]})")
                                << "keyframes[1].eye: required field missing";
        QTest::newRow("short eye")
            << QByteArray(R"({"keyframes": [{"eye": [0, 0, 4]}, {"eye": [1, 2]}]})")
            << "keyframes[1].eye: expected 3 numbers";
        QTest::newRow("eye on target")
            << QByteArray(R"({"keyframes": [{"eye": [0, 0, 4]}, {"eye": [0, 0, 0]}]})")
            << "keyframes[1]: eye and target coincide";
        QTest::newRow("fov") << QByteArray(
            R"({"keyframes": [{"eye": [0, 0, 4], "fov_deg": 180}, {"eye": [0, 1, 4]}]})")
                             << "keyframes[0].fov_deg:";
        QTest::newRow("too large")
            << QByteArray(R"({"keyframes": [{"eye": [0, 0, 1e300]}, {"eye": [0, 1, 4]}]})")
            << "keyframes[0].eye: expected 3 numbers";
        QTest::newRow("eye meets target between keyframes")
            << QByteArray(R"({"frames": 3, "keyframes": [{"eye": [0, 0, 4], "target": [0, 0, -4]},
                                                        {"eye": [0, 0, -4], "target": [0, 0, 4]}]})")
            << "frame 1, between keyframes[0] and [1]: eye and target coincide";
        QTest::newRow("huge literal")
            << QByteArray(R"({"keyframes": [{"eye": [0, 0, 1e999]}, {"eye": [0, 1, 4]}]})")
            << "keyframes[0].eye: expected 3 numbers";
    }

    void badKeyframesAreLocated()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, error);
        const Result<CameraPath> path = parseCameraPath(json, startCamera(), QStringLiteral("x"));
        QVERIFY(!path);
        QVERIFY2(path.error().startsWith(error), qPrintable(path.error()));
    }

    void missingFileSaysSo()
    {
        const Result<CameraPath> path =
            loadCameraPath(QStringLiteral("/nonexistent/path.json"), startCamera());
        QVERIFY(!path);
        QVERIFY2(path.error().startsWith(QStringLiteral("/nonexistent/path.json: cannot read")),
                 qPrintable(path.error()));
    }
};

QTEST_APPLESS_MAIN(TestCameraPath)
#include "tst_camerapath.moc"
