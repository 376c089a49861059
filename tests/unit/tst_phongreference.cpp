// The CPU reference against values worked out by hand (in the comments), so a
// mistake in PhongReference.cpp cannot hide behind the same mistake here.

#include "core/reference/PhongReference.h"
#include "core/scene/Transform.h"
#include "core/view/Camera.h"
#include "core/view/ObjectMatrices.h"

#include <QtTest>
#include <cmath>
#include <vector>

using namespace phonglab;

namespace {

constexpr double kTol = 1e-12;

bool near(const glm::dvec3 &a, const glm::dvec3 &b, double tol = kTol)
{
    return std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol;
}

QByteArray str(const glm::dvec3 &v)
{
    return QByteArray::number(v.x, 'g', 17) + ", " + QByteArray::number(v.y, 'g', 17) + ", "
        + QByteArray::number(v.z, 'g', 17);
}

#define COMPARE_VEC(actual, expected)                                                              \
    QVERIFY2(near(actual, expected), "got (" + str(actual) + "), expected (" + str(expected) + ")")

Material material(glm::dvec3 ka, glm::dvec3 kd, glm::dvec3 ks, double n)
{
    Material m;
    m.ka = ka;
    m.kd = kd;
    m.ks = ks;
    m.shininess = n;
    return m;
}

CameraSpaceLight light(glm::dvec3 position, glm::dvec3 Id = glm::dvec3(1.0),
                       glm::dvec3 Is = glm::dvec3(1.0), glm::dvec3 c = glm::dvec3(1.0, 0.0, 0.0))
{
    return CameraSpaceLight{position, Id, Is, c};
}

// Shared geometry for most cases: a surface point P = (0, 0, -5) facing the
// eye, N = (0, 0, 1), so V = (0, 0, 1).
const glm::dvec3 kP(0.0, 0.0, -5.0);
const glm::dvec3 kN(0.0, 0.0, 1.0);
// Light at (3, 0, -1): P→light = (3, 0, 4), d = 5, L = (0.6, 0, 0.8), N·L = 0.8,
// R = reflect(-L, N) = -L + 2(N·L)N = (-0.6, 0, 0.8), R·V = 0.8.
const glm::dvec3 kObliqueLight(3.0, 0.0, -1.0);
// Light at (0, 0, -3): straight above P, d = 2, L = N, N·L = 1, R·V = 1.
const glm::dvec3 kOverheadLight(0.0, 0.0, -3.0);

} // namespace

class TestPhongReference : public QObject
{
    Q_OBJECT

private slots:
    void diffuseOnly()
    {
        // ks = 0: I = kd·Id·N·L = (0.5, 0.25, 1)·0.8 = (0.4, 0.2, 0.8).
        const Material m = material(glm::dvec3(0.0), {0.5, 0.25, 1.0}, glm::dvec3(0.0), 8.0);
        const std::vector lights{light(kObliqueLight)};
        COMPARE_VEC(phongIntensity(kP, kN, m, glm::dvec3(0.3), lights), glm::dvec3(0.4, 0.2, 0.8));
    }

    void specularOnly()
    {
        // kd = 0, ks = 1, Is = (1, 0.5, 0.25), n = 2: I = Is·(R·V)² = Is·0.64.
        const Material m = material(glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(1.0), 2.0);
        const std::vector lights{light(kObliqueLight, glm::dvec3(1.0), {1.0, 0.5, 0.25})};
        COMPARE_VEC(phongIntensity(kP, kN, m, glm::dvec3(0.3), lights),
                    glm::dvec3(0.64, 0.32, 0.16));
    }

    void diffusePlusSpecularPlusAmbient()
    {
        // ka = 0.5, Ia = 0.2 -> 0.1; diffuse 0.5·0.8 = 0.4; specular 0.25·0.8¹ = 0.2.
        const Material m = material(glm::dvec3(0.5), glm::dvec3(0.5), glm::dvec3(0.25), 1.0);
        const std::vector lights{light(kObliqueLight)};
        COMPARE_VEC(phongIntensity(kP, kN, m, glm::dvec3(0.2), lights), glm::dvec3(0.7));
    }

    void twoLightsSum()
    {
        // Oblique light, Id = (1, 0, 0): kd·0.8 = (0.4, 0, 0).
        // Overhead light, Id = (0, 1, 0.5): kd·1 = (0, 0.5, 0.25).
        // Ambient 0.1·0.2 = 0.02 each channel. Sum (0.42, 0.52, 0.27).
        const Material m = material(glm::dvec3(0.1), glm::dvec3(0.5), glm::dvec3(0.0), 4.0);
        const std::vector lights{light(kObliqueLight, {1.0, 0.0, 0.0}),
                                 light(kOverheadLight, {0.0, 1.0, 0.5})};
        COMPARE_VEC(phongIntensity(kP, kN, m, glm::dvec3(0.2), lights),
                    glm::dvec3(0.42, 0.52, 0.27));
    }

    void attenuationClampedAtOne()
    {
        // c = (0.5, 0, 0): 1 / 0.5 = 2, clamped to 1, at any distance.
        const glm::dvec3 c(0.5, 0.0, 0.0);
        QCOMPARE(attenuationFactor(c, 0.0), 1.0);
        QCOMPARE(attenuationFactor(c, 2.0), 1.0);
        // Overhead light, kd = 0.5, N·L = 1: 0.5, not 1.0.
        const Material m = material(glm::dvec3(0.0), glm::dvec3(0.5), glm::dvec3(0.0), 1.0);
        const std::vector lights{light(kOverheadLight, glm::dvec3(1.0), glm::dvec3(1.0), c)};
        COMPARE_VEC(phongIntensity(kP, kN, m, glm::dvec3(0.0), lights), glm::dvec3(0.5));
    }

    void attenuationWithDistance()
    {
        // c = (1, 0.5, 0.25) at d = 2: 1 + 0.5·2 + 0.25·4 = 3 -> 1/3.
        const glm::dvec3 c(1.0, 0.5, 0.25);
        QVERIFY(std::abs(attenuationFactor(c, 2.0) - 1.0 / 3.0) < kTol);
        // At d = 0 the denominator is 1: no attenuation.
        QCOMPARE(attenuationFactor(c, 0.0), 1.0);
        // Overhead light (d = 2), kd = 0.6, ks = 0.3, N·L = R·V = 1:
        // (0.6 + 0.3)/3 = 0.3; attenuation scales specular too.
        const Material m = material(glm::dvec3(0.0), glm::dvec3(0.6), glm::dvec3(0.3), 5.0);
        const std::vector lights{light(kOverheadLight, glm::dvec3(1.0), glm::dvec3(1.0), c)};
        COMPARE_VEC(phongIntensity(kP, kN, m, glm::dvec3(0.0), lights), glm::dvec3(0.3));
    }

    void shininess_data()
    {
        QTest::addColumn<double>("n");
        QTest::addColumn<double>("expected");
        QTest::newRow("n=1") << 1.0 << 0.5;
        QTest::newRow("n=2") << 2.0 << 0.25;
        QTest::newRow("n=10") << 10.0 << 1.0 / 1024.0;
    }

    void shininess()
    {
        // P = (0, 0, -1), N = (0, 0, 1), V = (0, 0, 1). Light at (√3, 0, 0):
        // P→light = (√3, 0, 1), d = 2, L = (√3/2, 0, 1/2), N·L = 1/2,
        // R = (-√3/2, 0, 1/2), R·V = 1/2. kd = 0, ks = 1: I = 0.5ⁿ.
        QFETCH(double, n);
        QFETCH(double, expected);
        const Material m = material(glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(1.0), n);
        const std::vector lights{light({std::sqrt(3.0), 0.0, 0.0})};
        COMPARE_VEC(phongIntensity({0.0, 0.0, -1.0}, kN, m, glm::dvec3(0.0), lights),
                    glm::dvec3(expected));
    }

    void noSpecularFromBehind()
    {
        // P = (-4, 0, -3), N = (0, 0, 1), V = normalize(-P) = (0.8, 0, 0.6).
        // Light at (-8, 0, -6): L = (-0.8, 0, -0.6), N·L = -0.6 (behind).
        // R = -L + 2(N·L)N = (0.8, 0, -0.6), R·V = 0.64 - 0.36 = 0.28 > 0, so
        // the bare formula would add 0.28; the reference adds nothing.
        const Material m = material({0.5, 0.25, 1.0}, glm::dvec3(1.0), glm::dvec3(1.0), 1.0);
        const std::vector lights{light({-8.0, 0.0, -6.0})};
        COMPARE_VEC(phongIntensity({-4.0, 0.0, -3.0}, kN, m, {0.2, 0.4, 0.6}, lights),
                    glm::dvec3(0.1, 0.1, 0.6));
    }

    void ambientOnly()
    {
        // Ia·ka per channel: (0.2, 0.4, 0.6)·(0.5, 0.25, 1) = (0.1, 0.1, 0.6).
        const Material m = material({0.5, 0.25, 1.0}, glm::dvec3(1.0), glm::dvec3(1.0), 1.0);
        COMPARE_VEC(phongIntensity(kP, kN, m, {0.2, 0.4, 0.6}, {}), glm::dvec3(0.1, 0.1, 0.6));
    }

    void normalIsNormalised()
    {
        // Same as diffuseOnly with N given as (0, 0, 7).
        const Material m = material(glm::dvec3(0.0), {0.5, 0.25, 1.0}, glm::dvec3(0.0), 8.0);
        const std::vector lights{light(kObliqueLight)};
        COMPARE_VEC(phongIntensity(kP, {0.0, 0.0, 7.0}, m, glm::dvec3(0.0), lights),
                    glm::dvec3(0.4, 0.2, 0.8));
    }

    void encodeChannel_data()
    {
        QTest::addColumn<double>("intensity");
        QTest::addColumn<int>("expected");
        QTest::newRow("zero") << 0.0 << 0;
        QTest::newRow("just below 0.5/255") << 0.499 / 255.0 << 0;
        QTest::newRow("0.5/255 rounds up")
            << 0.5 / 255.0 << 1; // 0.5 is exact; lround rounds half away
        QTest::newRow("just above 0.5/255") << 0.501 / 255.0 << 1;
        QTest::newRow("half") << 0.5 << 128; // 127.5 -> 128
        QTest::newRow("254.49/255") << 254.49 / 255.0 << 254;
        QTest::newRow("one") << 1.0 << 255;
        QTest::newRow("negative") << -0.3 << 0;
        QTest::newRow("above one") << 1.7 << 255;
    }

    void encodeChannel()
    {
        QFETCH(double, intensity);
        QFETCH(int, expected);
        QCOMPARE(phonglab::encodeChannel(intensity), expected);
    }

    void transformOrder()
    {
        // p = (1, 1, 1). S(2, 3, 4): (2, 3, 4).
        // Rx(90°): (x, y·cos - z·sin, y·sin + z·cos) = (2, -4, 3).
        // Ry(90°): (x·cos + z·sin, y, -x·sin + z·cos) = (3, -4, -2).
        // Rz(90°): (x·cos - y·sin, x·sin + y·cos, z) = (4, 3, -2).
        // T(1, 2, 3): (5, 5, 1).
        Transform t;
        t.translate = {1.0, 2.0, 3.0};
        t.rotateDeg = {90.0, 90.0, 90.0};
        t.scale = {2.0, 3.0, 4.0};
        const glm::dvec3 p(t.matrix() * glm::dvec4(1.0, 1.0, 1.0, 1.0));
        COMPARE_VEC(p, glm::dvec3(5.0, 5.0, 1.0));
    }

    void lightToCameraSpaceIsAPoint()
    {
        // Camera at (0, 0, 4) looking at the origin: view = translate(0, 0, -4).
        // Light at (1, 2, 3) with w = 1 -> (1, 2, -1); with w = 0 it would stay (1, 2, 3).
        Camera camera;
        PointLight world;
        world.position = {1.0, 2.0, 3.0};
        world.diffuse = {0.1, 0.2, 0.3};
        world.specular = {0.4, 0.5, 0.6};
        world.attenuation = {1.0, 0.1, 0.01};
        const CameraSpaceLight cam = toCameraSpace(world, camera.viewMatrix());
        COMPARE_VEC(cam.position, glm::dvec3(1.0, 2.0, -1.0));
        QCOMPARE(cam.diffuse, world.diffuse);
        QCOMPARE(cam.specular, world.specular);
        QCOMPARE(cam.attenuation, world.attenuation);
    }

    void normalMatrixUnderNonUniformScale()
    {
        // Ellipsoid x²/4 + y² + z² = 1 (unit sphere scaled (2, 1, 1)). At object
        // point p = (1/√2, 1/√2, 0): normal n = p, tangents (-1/√2, 1/√2, 0) and (0, 0, 1).
        // Model maps the tangent to (-√2, 1/√2, 0). The normal matrix
        // (inverse transpose, here diag(1/2, 1, 1)) maps n to (1/(2√2), 1/√2, 0):
        // dot = -1/2 + 1/2 = 0. The model matrix itself maps n to (√2, 1/√2, 0):
        // dot = -2 + 1/2 = -1.5. A rotated camera must not change either fact.
        Transform t;
        t.scale = {2.0, 1.0, 1.0};
        Camera camera;
        camera.eye = {3.0, 2.0, 5.0};
        camera.target = {0.5, 0.0, -1.0};
        const ObjectMatrices m =
            ObjectMatrices::make(t.matrix(), camera.viewMatrix(), camera.projectionMatrix(1.0));
        const double s = 1.0 / std::sqrt(2.0);
        const glm::dvec3 n(s, s, 0.0);
        const glm::dmat3 linear(m.modelView);
        const glm::dvec3 normal = glm::normalize(m.normalMatrix * n);
        const glm::dvec3 skewed = glm::normalize(linear * n);
        for (const glm::dvec3 &tangent : {glm::dvec3(-s, s, 0.0), glm::dvec3(0.0, 0.0, 1.0)}) {
            const glm::dvec3 mapped = glm::normalize(linear * tangent);
            QVERIFY(std::abs(glm::dot(normal, mapped)) < kTol);
        }
        // Normalised: -1.5 / (|(√2, 1/√2, 0)|·|(-√2, 1/√2, 0)|) = -1.5 / 2.5 = -0.6.
        QVERIFY(std::abs(glm::dot(skewed, glm::normalize(linear * glm::dvec3(-s, s, 0.0))) + 0.6)
                < kTol);
    }
};

QTEST_APPLESS_MAIN(TestPhongReference)
#include "tst_phongreference.moc"
