// The classic shader mistakes: their stable keys, and the illumination
// equation with each pointwise mistake made, against values worked out by
// hand at points chosen so that the mistake shows.
#include "core/reference/PhongReference.h"
#include "core/reference/ShaderMistake.h"

#include <QTest>

#include <array>
#include <cmath>

using namespace phonglab;

namespace {

// Grey material and a white light, so every channel carries the same value.
Material material()
{
    Material m;
    m.ka = glm::dvec3(0.1);
    m.kd = glm::dvec3(0.5);
    m.ks = glm::dvec3(0.4);
    m.shininess = 2.0;
    return m;
}

const glm::dvec3 kAmbient(0.5);

CameraSpaceLight lightAt(const glm::dvec3 &position,
                         const glm::dvec3 &attenuation = {1.0, 0.0, 0.0})
{
    CameraSpaceLight light;
    light.position = position;
    light.attenuation = attenuation;
    return light;
}

double exact(const glm::dvec3 &p, const glm::dvec3 &n, const CameraSpaceLight &light)
{
    return phongTerms(p, n, material(), kAmbient, {&light, 1}).intensity.x;
}

double mistaken(const glm::dvec3 &p, const glm::dvec3 &n, const CameraSpaceLight &light,
                ShaderMistake mistake, int form = 0)
{
    return mistakenPhongTerms(p, n, material(), kAmbient, {&light, 1},
                              std::array{MistakeVariant{mistake, form}})
        .intensity.x;
}

// A surface facing the eye 5 units away, lit at 53° from its normal:
// L = (0.6, 0, 0.8), N·L = 0.8, R = (-0.6, 0, 0.8), R·V = 0.8, d = 5.
const glm::dvec3 kFacing(0.0, 0.0, -5.0);
const glm::dvec3 kUp(0.0, 0.0, 1.0);
const glm::dvec3 kLitFrom(3.0, 0.0, -1.0);
constexpr double kAmbientPart = 0.5 * 0.1;
constexpr double kDiffusePart = 0.5 * 0.8;
constexpr double kSpecularPart = 0.4 * 0.64; // 0.8^2

} // namespace

class TestShaderMistakes : public QObject
{
    Q_OBJECT

private slots:
    void keysAreStable()
    {
        const QStringList keys{"normal-matrix",     "unnormalized", "light-space", "homogeneous-w",
                               "reflect-incident",  "view-vector",  "attenuation", "negative-light",
                               "backface-specular", "ambient",      "gouraud",     "per-face",
                               "halfway-vector"};
        QCOMPARE(shaderMistakeKeys(), keys);
        for (const QString &key : keys) {
            const std::optional<ShaderMistake> mistake = shaderMistakeFromKey(key);
            QVERIFY2(mistake, qPrintable(key));
            QCOMPARE(shaderMistakeKey(*mistake), key);
            QVERIFY2(!shaderMistakeRule(*mistake).isEmpty(), qPrintable(key));
            QVERIFY2(!shaderMistakeSummary(*mistake).isEmpty(), qPrintable(key));
        }
        QVERIFY(!shaderMistakeFromKey(QStringLiteral("unknown")));
        QVERIFY(!shaderMistakeFromKey(QStringLiteral("Ambient")));
        QVERIFY(shaderMistakeRule(ShaderMistake::Attenuation).contains(QStringLiteral("c3·d²")));
    }

    void exactValueByHand()
    {
        QCOMPARE(exact(kFacing, kUp, lightAt(kLitFrom)),
                 kAmbientPart + kDiffusePart + kSpecularPart);
    }

    void reflectIncidentAndViewVectorLoseTheHighlight()
    {
        // reflect(L, N) = (0.6, 0, -0.8) and V = normalize(P) = (0, 0, -1)
        // each make R·V = -0.8: the highlight is gone, and the two images
        // are the same (check names both).
        const CameraSpaceLight light = lightAt(kLitFrom);
        const double reflected = mistaken(kFacing, kUp, light, ShaderMistake::ReflectIncident);
        const double view = mistaken(kFacing, kUp, light, ShaderMistake::ViewVector);
        QCOMPARE(reflected, kAmbientPart + kDiffusePart);
        QCOMPARE(view, reflected);
    }

    void attenuationLeftOut()
    {
        // f_att = 1 / (1 + 0.1·5) = 2/3.
        const CameraSpaceLight light = lightAt(kLitFrom, {1.0, 0.1, 0.0});
        QCOMPARE(exact(kFacing, kUp, light),
                 kAmbientPart + (kDiffusePart + kSpecularPart) * 2.0 / 3.0);
        QCOMPARE(mistaken(kFacing, kUp, light, ShaderMistake::Attenuation),
                 kAmbientPart + kDiffusePart + kSpecularPart);
    }

    // The other forms of the pointwise mistakes.
    void lightVectorUnnormalized()
    {
        // L = light - P = (3, 0, 4): N·L = 4, R = (-3, 0, 4), R·V = 4.
        QCOMPARE(mistaken(kFacing, kUp, lightAt(kLitFrom), ShaderMistake::Unnormalized,
                          MistakeForm::LightUnnormalized),
                 kAmbientPart + 0.5 * 4.0 + 0.4 * 16.0);
    }

    void attenuationUnclamped()
    {
        // c1 = 0.5: 1 / c1 = 2, which min(..., 1) brings back to 1.
        const CameraSpaceLight light = lightAt(kLitFrom, {0.5, 0.0, 0.0});
        QCOMPARE(exact(kFacing, kUp, light), kAmbientPart + kDiffusePart + kSpecularPart);
        QCOMPARE(mistaken(kFacing, kUp, light, ShaderMistake::Attenuation, MistakeForm::Unclamped),
                 kAmbientPart + 2.0 * (kDiffusePart + kSpecularPart));
    }

    void ambientOncePerLight()
    {
        const std::array lights{lightAt(kLitFrom), lightAt(kLitFrom)};
        const double twice =
            mistakenPhongTerms(
                kFacing, kUp, material(), kAmbient, lights,
                std::array{MistakeVariant{ShaderMistake::Ambient, MistakeForm::AmbientPerLight}})
                .intensity.x;
        QCOMPARE(twice, 2.0 * kAmbientPart + 2.0 * (kDiffusePart + kSpecularPart));
        QCOMPARE(mistaken(kFacing, kUp, lightAt(kLitFrom), ShaderMistake::Ambient,
                          MistakeForm::AmbientPerLight),
                 exact(kFacing, kUp, lightAt(kLitFrom))); // one light: the same image
    }

    void variantsHaveNames()
    {
        QStringList names;
        for (const MistakeVariant &v : allMistakeVariants()) {
            QVERIFY(!mistakeFormSummary(v).isEmpty());
            names << mistakeVariantName(v);
        }
        names.removeDuplicates();
        QCOMPARE(qsizetype(names.size()), qsizetype(allMistakeVariants().size()));
        QCOMPARE(mistakeFormCount(ShaderMistake::NormalMatrix), 3);
        QCOMPARE(mistakeFormCount(ShaderMistake::HomogeneousW), 3);
        QCOMPARE(mistakeFormCount(ShaderMistake::LightSpace), 2);
        QCOMPARE(mistakeVariantName({ShaderMistake::NormalMatrix, 0}),
                 QStringLiteral("normal-matrix"));
        QCOMPARE(mistakeVariantName({ShaderMistake::NormalMatrix, 2}),
                 QStringLiteral("normal-matrix/2"));
    }

    void ambientLeftOut()
    {
        QCOMPARE(mistaken(kFacing, kUp, lightAt(kLitFrom), ShaderMistake::Ambient),
                 kDiffusePart + kSpecularPart);
    }

    void unnormalizedNormal()
    {
        // N = (0, 0, 0.5): N·L = 0.4, and R = -L + 2(N·L)N = (-0.6, 0, -0.4)
        // points away from the eye.
        const glm::dvec3 shortNormal(0.0, 0.0, 0.5);
        QCOMPARE(exact(kFacing, shortNormal, lightAt(kLitFrom)),
                 kAmbientPart + kDiffusePart + kSpecularPart);
        QCOMPARE(mistaken(kFacing, shortNormal, lightAt(kLitFrom), ShaderMistake::Unnormalized),
                 kAmbientPart + 0.5 * 0.4);
    }

    void negativeLightDarkens()
    {
        // A light straight behind the surface: N·L = -1.
        const CameraSpaceLight behind = lightAt({0.0, 0.0, -10.0});
        QCOMPARE(exact(kFacing, kUp, behind), kAmbientPart);
        QCOMPARE(mistaken(kFacing, kUp, behind, ShaderMistake::NegativeLight), kAmbientPart - 0.5);
        QCOMPARE(mistaken(kFacing, kUp, behind, ShaderMistake::BackfaceSpecular), kAmbientPart);
    }

    void backfaceSpecular()
    {
        // Seen at a grazing angle, V = (0.8, 0, 0.6), with the light below
        // the surface almost opposite the eye, L = (-0.8, 0, -0.6): N·L =
        // -0.6 but R·V = 1 - 2·0.6·0.6 = 0.28.
        const glm::dvec3 grazing(-4.0, 0.0, -3.0);
        const CameraSpaceLight light = lightAt({-8.0, 0.0, -6.0});
        QCOMPARE(exact(grazing, kUp, light), kAmbientPart);
        const double withHighlight = mistaken(grazing, kUp, light, ShaderMistake::BackfaceSpecular);
        QVERIFY(std::abs(withHighlight - (kAmbientPart + 0.4 * 0.28 * 0.28)) < 1e-12);
        QCOMPARE(mistaken(grazing, kUp, light, ShaderMistake::NegativeLight),
                 kAmbientPart - 0.5 * 0.6);
    }

    void halfwayVector()
    {
        // H = normalize(L + V) = (0.6, 0, 1.8) / |.|: N·H = 0.9487, (N·H)² = 0.9.
        const CameraSpaceLight light = lightAt(kLitFrom);
        QVERIFY(std::abs(mistaken(kFacing, kUp, light, ShaderMistake::HalfwayVector)
                         - (kAmbientPart + kDiffusePart + 0.4 * 0.9))
                < 1e-12);
        // With Blinn's 4n: (N·H)^8 = 0.9^4.
        QVERIFY(std::abs(mistaken(kFacing, kUp, light, ShaderMistake::HalfwayVector,
                                  MistakeForm::BlinnExponent)
                         - (kAmbientPart + kDiffusePart + 0.4 * 0.6561))
                < 1e-12);
    }

    void hardCodedAttenuationAndAttenuatedAmbient()
    {
        const CameraSpaceLight light = lightAt(kLitFrom, {1.0, 0.1, 0.0}); // f_att = 2/3 at d = 5
        const double lit = kDiffusePart + kSpecularPart;
        QVERIFY(std::abs(mistaken(kFacing, kUp, light, ShaderMistake::Attenuation,
                                  MistakeForm::InverseSquare)
                         - (kAmbientPart + lit / 25.0))
                < 1e-12);
        QVERIFY(std::abs(mistaken(kFacing, kUp, light, ShaderMistake::Attenuation,
                                  MistakeForm::LearnOpenGl)
                         - (kAmbientPart + lit / (1.0 + 0.45 + 0.8)))
                < 1e-12);
        QVERIFY(std::abs(mistaken(kFacing, kUp, light, ShaderMistake::Ambient,
                                  MistakeForm::AmbientAttenuated)
                         - (kAmbientPart + lit) * 2.0 / 3.0)
                < 1e-12);
    }

    void mistakesCombineAsRealCodeMakesThem()
    {
        // N·L unclamped and the specular unguarded, together: the diffuse
        // term goes negative and the highlight stays.
        const glm::dvec3 grazing(-4.0, 0.0, -3.0);
        const CameraSpaceLight below = lightAt({-8.0, 0.0, -6.0});
        const std::array both{MistakeVariant{ShaderMistake::NegativeLight, 0},
                              MistakeVariant{ShaderMistake::BackfaceSpecular, 0}};
        const double value =
            mistakenPhongTerms(grazing, kUp, material(), kAmbient, {&below, 1}, both).intensity.x;
        QVERIFY(std::abs(value - (kAmbientPart - 0.5 * 0.6 + 0.4 * 0.28 * 0.28)) < 1e-12);
        // Blinn's halfway vector and no attenuation.
        const CameraSpaceLight far = lightAt(kLitFrom, {1.0, 0.1, 0.0});
        const std::array blinnUnattenuated{MistakeVariant{ShaderMistake::HalfwayVector, 0},
                                           MistakeVariant{ShaderMistake::Attenuation, 0}};
        const double blinn =
            mistakenPhongTerms(kFacing, kUp, material(), kAmbient, {&far, 1}, blinnUnattenuated)
                .intensity.x;
        QVERIFY(std::abs(blinn - (kAmbientPart + kDiffusePart + 0.4 * 0.9)) < 1e-12);
    }

    void otherMistakesLeaveThePointAlone()
    {
        // These change the inputs (normal, position, lights) or where the
        // equation is evaluated, not the equation at a point.
        const CameraSpaceLight light = lightAt(kLitFrom, {1.0, 0.1, 0.02});
        for (ShaderMistake m :
             {ShaderMistake::NormalMatrix, ShaderMistake::LightSpace, ShaderMistake::HomogeneousW,
              ShaderMistake::Gouraud, ShaderMistake::PerFace}) {
            QVERIFY(!isPointwiseMistake(m));
            QCOMPARE(mistaken(kFacing, kUp, light, m), exact(kFacing, kUp, light));
        }
    }

    void everyPointwiseMistakeShowsSomewhere()
    {
        // A mistake that changed no value at these points would be no test
        // of the ranking built on them.
        const CameraSpaceLight lit = lightAt(kLitFrom, {1.0, 0.1, 0.0});
        const CameraSpaceLight behind = lightAt({0.0, 0.0, -10.0});
        const CameraSpaceLight grazingLight = lightAt({-8.0, 0.0, -6.0});
        const glm::dvec3 grazing(-4.0, 0.0, -3.0);
        for (const QString &key : shaderMistakeKeys()) {
            const ShaderMistake m = *shaderMistakeFromKey(key);
            if (!isPointwiseMistake(m))
                continue;
            const bool shows = mistaken(kFacing, kUp, lit, m) != exact(kFacing, kUp, lit)
                || mistaken(kFacing, glm::dvec3(0.0, 0.0, 0.5), lit, m)
                    != exact(kFacing, glm::dvec3(0.0, 0.0, 0.5), lit)
                || mistaken(kFacing, kUp, behind, m) != exact(kFacing, kUp, behind)
                || mistaken(grazing, kUp, grazingLight, m) != exact(grazing, kUp, grazingLight);
            QVERIFY2(shows, qPrintable(key));
        }
    }
};

QTEST_GUILESS_MAIN(TestShaderMistakes)
#include "tst_shadermistakes.moc"
