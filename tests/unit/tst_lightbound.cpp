// Leaving out lights that cannot be seen (LightBound.h): the bound is never
// below what a light really adds at any point of the object with any
// normal and view, and a light that could change a pixel by the allowance
// is never left out, alone or together with others.

#include "core/reference/LightBound.h"
#include "core/reference/PhongReference.h"

#include <QRandomGenerator>
#include <QtTest>

using namespace phonglab;

namespace {

glm::dvec3 randomUnit(QRandomGenerator &random)
{
    for (;;) {
        const glm::dvec3 v(random.generateDouble() * 2 - 1, random.generateDouble() * 2 - 1,
                           random.generateDouble() * 2 - 1);
        const double len = glm::length(v);
        if (len > 1e-3 && len <= 1.0)
            return v / len;
    }
}

glm::dvec3 randomColor(QRandomGenerator &random, double scale)
{
    return scale
        * glm::dvec3(random.generateDouble(), random.generateDouble(), random.generateDouble());
}

PointLight randomLight(QRandomGenerator &random)
{
    PointLight light;
    light.position = randomUnit(random) * (random.generateDouble() * 30.0);
    light.diffuse = randomColor(random, 2.0);
    light.specular = randomColor(random, 2.0);
    light.attenuation = {random.generateDouble(), random.generateDouble() * 0.5,
                         random.generateDouble() * 0.2};
    if (light.attenuation.x + light.attenuation.y + light.attenuation.z <= 0.0)
        light.attenuation.x = 1.0;
    return light;
}

Material randomMaterial(QRandomGenerator &random)
{
    Material m;
    m.ka = randomColor(random, 1.0);
    m.kd = randomColor(random, 1.0);
    m.ks = randomColor(random, 1.0);
    m.shininess = 1.0 + random.generateDouble() * 100.0;
    return m;
}

// What the light really adds at point p (world = camera here: the eye at
// the origin) with normal n, in the largest channel.
double actualContribution(const PointLight &light, const Material &material, const glm::dvec3 &p,
                          const glm::dvec3 &n)
{
    const CameraSpaceLight l{light.position, light.diffuse, light.specular, light.attenuation};
    const glm::dvec3 with = phongIntensity(p, n, material, glm::dvec3(0.0), std::span(&l, 1));
    return std::max({with.r, with.g, with.b});
}

} // namespace

class TestLightBound : public QObject
{
    Q_OBJECT

private slots:
    void boundHoldsEverywhereOnTheObject()
    {
        QRandomGenerator random(20261125);
        int tight = 0;
        for (int trial = 0; trial < 2000; ++trial) {
            const PointLight light = randomLight(random);
            const Material material = randomMaterial(random);
            const BoundingSphere bounds{randomUnit(random) * (random.generateDouble() * 10.0),
                                        0.1 + random.generateDouble() * 3.0};
            const double bound = maxLightContribution(light, material, bounds);
            double worst = 0.0;
            for (int s = 0; s < 50; ++s) {
                const glm::dvec3 p = bounds.center
                    + randomUnit(random) * bounds.radius * std::cbrt(random.generateDouble());
                // Any normal, and half the time the one facing the light, with
                // the eye on its mirror ray: the largest the terms can be.
                glm::dvec3 n = randomUnit(random);
                if (s % 2 == 0 && glm::length(light.position - p) > 1e-9)
                    n = glm::normalize(light.position - p);
                worst = std::max(worst, actualContribution(light, material, p, n));
            }
            QVERIFY2(worst <= bound * (1 + 1e-12) + 1e-15,
                     qPrintable(QStringLiteral("trial %1: %2 above the bound %3")
                                    .arg(trial)
                                    .arg(worst)
                                    .arg(bound)));
            tight += worst > 0.5 * bound ? 1 : 0;
        }
        // A bound far above anything reached would keep every light.
        QVERIFY2(tight > 200, qPrintable(QString::number(tight)));
    }

    void boundIsReachedFacingTheLight()
    {
        // At the nearest point, facing the light, the eye on the mirror ray:
        // diffuse and specular at their peak, so the bound is exact there.
        // The eye (the origin) behind the light, both on the normal.
        PointLight light;
        light.position = {0, 0, -5};
        light.attenuation = {1, 0.1, 0.01};
        Material m;
        m.kd = {0.5, 0.5, 0.5};
        m.ks = {0.3, 0.3, 0.3};
        const BoundingSphere bounds{{0, 0, -10}, 1.0};
        const double expected = attenuationFactor(light.attenuation, 4.0) * 0.8;
        QCOMPARE(maxLightContribution(light, m, bounds), expected);
        QCOMPARE(actualContribution(light, m, {0, 0, -9}, {0, 0, 1}), expected);
        light.enabled = false;
        QCOMPARE(maxLightContribution(light, m, bounds), 0.0);
    }

    void neverLeavesOutALightThatCouldChangeAPixel()
    {
        QRandomGenerator random(7);
        int leftOut = 0;
        for (int trial = 0; trial < 3000; ++trial) {
            std::vector<PointLight> lights(std::size_t(random.bounded(0, kMaxLights + 1)));
            for (PointLight &light : lights) {
                light = randomLight(random);
                light.position *= 5.0; // many far away and dim
                light.enabled = random.bounded(6) != 0;
            }
            const Material material = randomMaterial(random);
            const BoundingSphere bounds{{0, 0, 0}, 1.0};
            const double allowance = random.bounded(1, 6) / 255.0;
            const LightSelection chosen = selectLights(lights, material, bounds, allowance);

            double sum = 0.0;
            for (int i : chosen.leftOut) {
                const double bound = maxLightContribution(lights[std::size_t(i)], material, bounds);
                QVERIFY2(bound < allowance, "a light that could change a pixel was left out");
                sum += bound;
            }
            QVERIFY(sum < allowance);
            QCOMPARE(chosen.leftOutBound, sum);
            // Every enabled light is in exactly one list; no disabled one is.
            QCOMPARE(chosen.kept.size() + chosen.leftOut.size(), enabledLights(lights).size());
            for (int i : chosen.kept)
                QVERIFY(lights[std::size_t(i)].enabled);
            // Greedy by smallest bound: the smallest kept light would not have fitted.
            if (!chosen.kept.empty()) {
                double smallestKept = std::numeric_limits<double>::infinity();
                for (int i : chosen.kept)
                    smallestKept =
                        std::min(smallestKept,
                                 maxLightContribution(lights[std::size_t(i)], material, bounds));
                QVERIFY(!(sum + smallestKept < allowance));
            }
            leftOut += int(chosen.leftOut.size());
        }
        QVERIFY2(leftOut > 100,
                 "the random scenes never left a light out: the test proves nothing");
    }

    void keepsEverythingWithoutAnAllowance()
    {
        std::vector<PointLight> lights(3);
        lights[0].position = {1000, 0, 0};
        lights[1].enabled = false;
        lights[2].position = {0, 1e6, 0};
        lights[2].attenuation = {0, 0, 1};
        const LightSelection none = selectLights(lights, Material(), {{0, 0, 0}, 1.0}, 0.0);
        QCOMPARE(none.kept, (std::vector<int>{0, 2}));
        QVERIFY(none.leftOut.empty());
        const LightSelection some = selectLights(lights, Material(), {{0, 0, 0}, 1.0}, 2.0 / 255);
        QCOMPARE(some.kept, (std::vector<int>{0}));
        QCOMPARE(some.leftOut, (std::vector<int>{2}));
    }
};

QTEST_APPLESS_MAIN(TestLightBound)
#include "tst_lightbound.moc"
