// Diagnosis on the reference's own images: a render that is the reference
// with one mistake made must be diagnosed as that mistake (or the group of
// mistakes that give the same image), with full confidence; the exact
// image has no finding; noise is unexplained; a mistake the scene cannot
// show is listed as undetectable.
#include "MistakeScenes.h"
#include "core/check/MistakeDiagnosis.h"
#include "core/reference/MeshRaycaster.h"

#include <QRandomGenerator>
#include <QTest>

#include <algorithm>

using namespace phonglab;
using phonglab::test::mistakeScene;

namespace {

constexpr int kSize = 64;
const glm::dvec3 kBackground(0.1);

ReferenceImage render(const Scene &s, const ReferenceShader &shader)
{
    return *raycastScene(s, kSize, kSize, shader);
}

struct Setup {
    ReferenceImage exact;
    std::vector<std::pair<MistakeVariant, ReferenceImage>> mistaken;
    std::vector<std::uint8_t> compared; // covered pixels
};

Setup setup(const Scene &s)
{
    Setup out;
    out.exact = render(s, ReferenceShading::Phong);
    for (const QString &key : shaderMistakeKeys()) {
        const ShaderMistake m = *shaderMistakeFromKey(key);
        out.mistaken.emplace_back(MistakeVariant{m}, render(s, {ReferenceShading::Phong, m}));
    }
    out.compared = out.exact.coverage;
    return out;
}

MistakeDiagnosis diagnose(const Setup &s, const RgbImage &yours)
{
    return diagnoseMistakes(yours, s.exact, s.mistaken, s.compared, 2, kBackground);
}

} // namespace

class TestMistakeDiagnosis : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { m_setup = setup(mistakeScene()); }

    void exactRenderHasNoFinding()
    {
        const MistakeDiagnosis d = diagnose(m_setup, m_setup.exact.toImage(kBackground));
        QCOMPARE(d.differingPixels, 0);
        QVERIFY(d.findings.empty());
        QVERIFY(!d.unexplained());
    }

    void eachMistakeIsNamed_data()
    {
        QTest::addColumn<QString>("key");
        for (const QString &key : shaderMistakeKeys())
            // The ray caster cannot make these: no triangles (tst_mistakenreference).
            if (key != QLatin1String("gouraud") && key != QLatin1String("per-face"))
                QTest::newRow(qPrintable(key)) << key;
    }

    void eachMistakeIsNamed()
    {
        // The confusion matrix on the reference's own images: each mistake's
        // image is diagnosed as that mistake first, and fully explained.
        QFETCH(QString, key);
        const ShaderMistake mistake = *shaderMistakeFromKey(key);
        const auto made =
            std::find_if(m_setup.mistaken.begin(), m_setup.mistaken.end(),
                         [&](const auto &entry) { return entry.first.key == mistake; });
        const MistakeDiagnosis d = diagnose(m_setup, made->second.toImage(kBackground));
        QVERIFY(d.differingPixels > 0);
        QVERIFY(!d.findings.empty());
        const MistakeFinding &top = d.findings.front();
        const bool named = top.key == mistake
            || std::find(top.also.begin(), top.also.end(), mistake) != top.also.end();
        QVERIFY2(
            named,
            qPrintable(QStringLiteral("%1 diagnosed as %2").arg(key, shaderMistakeKey(top.key))));
        QCOMPARE(top.confidence, 1.0);
        QVERIFY(!d.unexplained());
        // Nothing else explains it as well, unless it gives the same image.
        for (std::size_t i = 1; i < d.findings.size(); ++i)
            QVERIFY2(d.findings[i].confidence < 1.0,
                     qPrintable(shaderMistakeKey(d.findings[i].key)));
    }

    void reflectIncidentAndViewVectorAreOneFinding()
    {
        const auto made =
            std::find_if(m_setup.mistaken.begin(), m_setup.mistaken.end(), [](const auto &entry) {
                return entry.first.key == ShaderMistake::ViewVector;
            });
        const MistakeDiagnosis d = diagnose(m_setup, made->second.toImage(kBackground));
        QCOMPARE(d.findings.front().key, ShaderMistake::ReflectIncident);
        QVERIFY(d.findings.front().also == std::vector<ShaderMistake>{ShaderMistake::ViewVector});
    }

    void noiseIsUnexplained()
    {
        RgbImage noise(kSize, kSize);
        QRandomGenerator rng(7);
        for (std::uint8_t &byte : noise.bytes)
            byte = std::uint8_t(rng.bounded(256));
        const MistakeDiagnosis d = diagnose(m_setup, noise);
        QVERIFY(d.differingPixels > 0);
        QVERIFY(d.unexplained());
    }

    void renderOfAnotherSizeDiffersEverywhere()
    {
        const MistakeDiagnosis d = diagnose(m_setup, RgbImage(kSize / 2, kSize));
        QCOMPARE(d.differingPixels, m_setup.exact.coveredCount());
        QVERIFY(d.findings.empty());
        QVERIFY(d.unexplained());
    }

    void uniformScaleHidesTheNormalMatrix()
    {
        const Setup uniform = setup(mistakeScene(glm::dvec3(0.8)));
        const MistakeDiagnosis d = diagnose(uniform, uniform.exact.toImage(kBackground));
        QVERIFY(std::find(d.undetectable.begin(), d.undetectable.end(), ShaderMistake::NormalMatrix)
                != d.undetectable.end());
        QVERIFY(std::find(d.undetectable.begin(), d.undetectable.end(), ShaderMistake::Ambient)
                == d.undetectable.end());
    }

private:
    Setup m_setup;
};

QTEST_GUILESS_MAIN(TestMistakeDiagnosis)
#include "tst_mistakediagnosis.moc"
