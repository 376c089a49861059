// The check's reference on its own scene (assets/scenes/check.json), without
// a GPU: every mistake's image, diagnosed, names that mistake first with full
// confidence (reflect-incident and view-vector together: they always give the
// same image); none is undetectable there; the exact image passes.
#include "CheckScene.h"
#include "core/check/PixelTerms.h"

#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

class TestCheckReference : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        m_scene = loadCheckScene();
        m_reference = makeTestCheckReference(m_scene);
    }

    void everyMistakeShowsInTheCheckScene()
    {
        QStringList hidden;
        for (ShaderMistake m : m_reference.undetectable)
            hidden << shaderMistakeKey(m);
        QVERIFY2(hidden.isEmpty(),
                 qPrintable(hidden.join(QStringLiteral(", ")) + QStringLiteral(" cannot show")));
        QCOMPARE(m_reference.mistaken.size(), allMistakeVariants().size());
    }

    void exactImagePasses()
    {
        const CheckReport report =
            checkRender(m_reference.exact.toImage(m_scene.background), m_reference);
        QVERIFY(report.passed());
        QCOMPARE(report.comparison.maxError, 0);
        QVERIFY(report.diagnosis.findings.empty());
    }

    // Over every form of every mistake: each is named by its
    // key, first, and the form found is its own.
    void confusionMatrix_data()
    {
        QTest::addColumn<int>("variant");
        const std::vector<MistakeVariant> variants = allMistakeVariants();
        for (std::size_t i = 0; i < variants.size(); ++i)
            QTest::newRow(qPrintable(mistakeVariantName(variants[i]))) << int(i);
    }

    void confusionMatrix()
    {
        QFETCH(int, variant);
        const MistakeVariant made = allMistakeVariants()[std::size_t(variant)];
        const ShaderMistake mistake = made.key;
        const QString key = mistakeVariantName(made);
        const auto it = std::find_if(m_reference.mistaken.begin(), m_reference.mistaken.end(),
                                     [&](const auto &p) { return p.first == made; });
        QVERIFY(it != m_reference.mistaken.end());
        if (it->second == m_reference.exactImage)
            QSKIP("this form gives the exact image in this scene");
        // The guarded equation demanded: backface-specular's image is the
        // slide's equation, which passes by default.
        const CheckReport report = checkRender(it->second, m_reference, kDefaultCheckToleranceSteps,
                                               PhongEquation::Guarded);
        QVERIFY(!report.passed());
        QVERIFY(!report.diagnosis.findings.empty());
        const MistakeFinding &top = report.diagnosis.findings.front();
        const bool named = top.key == mistake
            || std::find(top.also.begin(), top.also.end(), mistake) != top.also.end();
        QVERIFY2(
            named,
            qPrintable(QStringLiteral("%1 diagnosed as %2").arg(key, shaderMistakeKey(top.key))));
        QCOMPARE(top.confidence, 1.0);
        // Another form, or another key beside it, only where its image is
        // this one (this camera has no rotation: M and MV move N alike, a
        // light with w = 0 stays where world coordinates put it).
        const auto sameImage = [&](ShaderMistake k, std::optional<int> form) {
            return std::any_of(m_reference.mistaken.begin(), m_reference.mistaken.end(),
                               [&](const auto &p) {
                                   return p.first.key == k && (!form || p.first.form == *form)
                                       && p.second == it->second;
                               });
        };
        QVERIFY2(sameImage(top.key, top.form),
                 qPrintable(key + QStringLiteral(" found as form %1").arg(top.form)));
        for (ShaderMistake also : top.also)
            QVERIFY2(sameImage(also, std::nullopt), qPrintable(shaderMistakeKey(also)));
        // reflect-incident and view-vector always look the same.
        if (mistake == ShaderMistake::ReflectIncident || mistake == ShaderMistake::ViewVector)
            QCOMPARE(int(top.also.size()), 1);
        if (report.diagnosis.findings.size() > 1)
            QVERIFY(report.diagnosis.findings[1].confidence < 1.0);
    }

    void worstPixelNamesItsObject()
    {
        const auto &[mistake, image] = m_reference.mistaken.front();
        const CheckReport report = checkRender(image, m_reference);
        QCOMPARE(report.worstObject, 0);
        QVERIFY(report.badFraction() > 0.0 && report.badFraction() <= 1.0);
    }

    // The inspector's terms add up to the reference's pixel, and they are
    // the equation's: unit N, L, V; R the mirror of L about N.
    void pixelTermsSumToTheReference()
    {
        int checked = 0;
        for (int y = 0; y < kCheckHeight; y += 7) {
            for (int x = 0; x < kCheckWidth; x += 7) {
                const std::optional<PixelTerms> t =
                    pixelTerms(m_reference.hits, m_scene, ReferenceShading::Phong, x, y);
                QCOMPARE(t.has_value(), m_reference.exact.covered(x, y));
                if (!t)
                    continue;
                ++checked;
                const glm::dvec3 d = t->intensity - m_reference.exact.colorAt(x, y);
                QVERIFY(glm::length(d) < 1e-12);
                QVERIFY(std::abs(glm::length(t->N) - 1.0) < 1e-12);
                for (const LightTerms &l : t->lights) {
                    QVERIFY(std::abs(glm::dot(l.R, t->N) - glm::dot(l.L, t->N)) < 1e-12);
                    QVERIFY(l.attenuation > 0.0 && l.attenuation <= 1.0);
                }
            }
        }
        QVERIFY(checked > 100);
        QVERIFY(!pixelTerms(m_reference.hits, m_scene, ReferenceShading::Phong, 0,
                            0)); // the corner is background
        const std::optional<PixelTerms> centre = pixelTerms(
            m_reference.hits, m_scene, ReferenceShading::Phong, kCheckWidth / 2, kCheckHeight / 2);
        QVERIFY(centre && centre->toText().contains(QStringLiteral("f_att")));
    }

    // The slide's equation: its terms add up to its own image,
    // which differs from the guarded one where a light behind leaves a
    // highlight, and the text says which equation they are of.
    void pixelTermsOfTheSlidesEquation()
    {
        int checked = 0, differing = 0;
        for (int y = 0; y < kCheckHeight; y += 3) {
            for (int x = 0; x < kCheckWidth; x += 3) {
                const std::optional<PixelTerms> t = pixelTerms(
                    m_reference.hits, m_scene, ReferenceShading::Phong, x, y, PhongEquation::Slide);
                if (!t)
                    continue;
                ++checked;
                QVERIFY(glm::length(t->intensity - m_reference.slide.colorAt(x, y)) < 1e-12);
                differing += glm::length(t->intensity - m_reference.exact.colorAt(x, y)) > 1e-6;
            }
        }
        QVERIFY(checked > 1000);
        QVERIFY2(differing > 20, qPrintable(QString::number(differing)));
        const std::optional<PixelTerms> centre =
            pixelTerms(m_reference.hits, m_scene, ReferenceShading::Phong, kCheckWidth / 2,
                       kCheckHeight / 2, PhongEquation::Slide);
        QVERIFY(centre && centre->toText().contains(QStringLiteral("slide")));
    }

    // For the other exact methods the terms are theirs: Blinn-Phong's with
    // the half vector, the normals view's colour.
    void pixelTermsFollowTheMethod_data()
    {
        QTest::addColumn<QString>("method");
        QTest::newRow("blinn-phong") << QStringLiteral("blinn-phong");
        QTest::newRow("normals") << QStringLiteral("normals");
    }

    void pixelTermsFollowTheMethod()
    {
        QFETCH(QString, method);
        Scene scene = m_scene;
        scene.shading = *shadingFromName(method);
        const CheckReference reference = makeTestCheckReference(scene);
        int checked = 0;
        for (int y = 0; y < kCheckHeight; y += 9) {
            for (int x = 0; x < kCheckWidth; x += 9) {
                const std::optional<PixelTerms> t =
                    pixelTerms(reference.hits, scene, reference.shader.shading, x, y);
                if (!t)
                    continue;
                ++checked;
                QVERIFY(glm::length(t->intensity - reference.exact.colorAt(x, y)) < 1e-12);
            }
        }
        QVERIFY(checked > 100);
    }

private:
    Scene m_scene;
    CheckReference m_reference;
};

QTEST_GUILESS_MAIN(TestCheckReference)
#include "tst_checkreference.moc"
