// The check's confusion matrix on the GPU: each classic mistake made in the
// shipped Phong shaders (ShaderMutations.h), rendered on the check scene
// (assets/scenes/check.json), must be diagnosed with its own key first
// (reflect-incident and view-vector as one finding naming both); the shipped
// shaders of the exact methods must pass.
#include "CheckScene.h"
#include "ResultChecks.h"
#include "ShaderMutations.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/QtImages.h"

#include <QTest>

#include <map>

using namespace phonglab;
using namespace phonglab::test;

class TestCheckMistakes : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        m_scene = loadCheckScene();
        m_reference = makeTestCheckReference(m_scene);
        QVERIFY_OK(m_offscreen.create());
        QVERIFY_OK(m_offscreen.renderer().setScene(m_scene));
    }

    void shippedShadersPass_data()
    {
        QTest::addColumn<QString>("method");
        QTest::newRow("phong") << QStringLiteral("phong");
        QTest::newRow("blinn-phong") << QStringLiteral("blinn-phong");
        QTest::newRow("normals") << QStringLiteral("normals");
    }

    void shippedShadersPass()
    {
        QFETCH(QString, method);
        Scene scene = m_scene;
        scene.shading = *shadingFromName(method);
        const CheckReference reference = makeTestCheckReference(scene);
        const Result<StageSources> shipped =
            readStageFiles(sourcePath(QStringLiteral("shaders/%1.vert").arg(method)),
                           sourcePath(QStringLiteral("shaders/%1.frag").arg(method)));
        QVERIFY2(shipped, qPrintable(shipped.error()));
        const CheckReport report =
            checkRender(toRgbImage(render(shipped->vertex, shipped->fragment)), reference);
        QVERIFY2(report.passed(), qPrintable(checkSummary(report)));
        QVERIFY(report.comparison.pixelsCompared > 10000);
    }

    // Every mistake made in turn; row = the mistake made, column = how much
    // of the difference each key's image explains (grouped keys share their
    // finding's value; unlisted findings are below 10 %). Printed as a table,
    // the diagonal asserted to win its row outright.
    void confusionMatrix()
    {
        const QStringList keys = shaderMistakeKeys();
        QStringList table{QStringLiteral("| made \\ found | ") + keys.join(QStringLiteral(" | "))
                              + QStringLiteral(" |"),
                          QStringLiteral("|---") + QStringLiteral("|---").repeated(keys.size())
                              + QStringLiteral("|")};
        for (const QString &key : keys) {
            const ShaderMistake mistake = *shaderMistakeFromKey(key);
            const ShaderPair shaders = withMistake(mistake);
            // The guarded equation demanded: by default the slide's literal
            // one (backface-specular's image) passes too.
            const CheckReport report =
                checkRender(toRgbImage(render(shaders.vertex, shaders.fragment)), m_reference,
                            kDefaultCheckToleranceSteps, PhongEquation::Guarded);
            QVERIFY2(!report.passed(),
                     qPrintable(key + QStringLiteral(": ") + checkSummary(report)));
            std::map<ShaderMistake, double> row;
            for (const MistakeFinding &f : report.diagnosis.findings) {
                row[f.key] = f.confidence;
                for (ShaderMistake m : f.also)
                    row[m] = f.confidence;
            }
            const MistakeFinding &top = report.diagnosis.findings.front();
            const bool named = top.key == mistake
                || std::find(top.also.begin(), top.also.end(), mistake) != top.also.end();
            QVERIFY2(named && top.confidence >= kExplainedConfidence,
                     qPrintable(key + QStringLiteral(": ") + checkSummary(report)));
            if (report.diagnosis.findings.size() > 1)
                QVERIFY2(report.diagnosis.findings[1].confidence < top.confidence,
                         qPrintable(key + QStringLiteral(": a tie with ")
                                    + shaderMistakeKey(report.diagnosis.findings[1].key)));
            QString line = QStringLiteral("| %1 |").arg(key);
            for (const QString &column : keys) {
                const double c = row.count(*shaderMistakeFromKey(column))
                    ? row[*shaderMistakeFromKey(column)]
                    : 0.0;
                line += c > 0.0 ? QStringLiteral(" %1 |").arg(qRound(100.0 * c))
                                : QStringLiteral(" · |");
            }
            table << line;
        }
        qInfo("confusion matrix on %s, %dx%d, %% of the difference explained:\n%s",
              "assets/scenes/check.json", kCheckWidth, kCheckHeight,
              qPrintable(table.join(QLatin1Char('\n'))));
    }

    // Every form of every mistake, on turnedScene(): each
    // variant, made in GLSL as a student writes it, is named by its key
    // first and alone; the table says which form was found.
    void variantConfusionMatrix()
    {
        const Scene scene = turnedScene();
        const CheckReference reference = makeTestCheckReference(scene);
        QVERIFY_OK(m_offscreen.renderer().setScene(scene));
        QStringList table{QStringLiteral("| made | found first | % | form found |"),
                          QStringLiteral("|---|---|---|---|")};
        QStringList failures;
        for (const MistakeVariant &made : allMistakeVariants()) {
            CheckReport report;
            const QString failure = checkMistake(withMistake(made), reference, made,
                                                 PhongEquation::Guarded, true, report);
            if (!failure.isEmpty())
                failures << failure;
            if (report.diagnosis.findings.empty())
                continue;
            const MistakeFinding &top = report.diagnosis.findings.front();
            table << QStringLiteral("| %1 | %2 | %3 | %4 |")
                         .arg(mistakeVariantName(made), shaderMistakeKey(top.key))
                         .arg(qRound(100.0 * top.confidence))
                         .arg(mistakeFormSummary({top.key, top.form}));
        }
        QVERIFY_OK(m_offscreen.renderer().setScene(m_scene));
        qInfo("every form of every mistake, check scene turned, %dx%d:\n%s", kCheckWidth,
              kCheckHeight, qPrintable(table.join(QLatin1Char('\n'))));
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join(QLatin1Char('\n'))));
    }

    // A student who writes the slide's equation makes the same mistakes:
    // each is named by its key first, as in the guarded one; the table says which equation checked it (the guarded one where
    // a mistake leaves no highlight behind a surface to tell the two apart).
    void mistakesInTheSlidesEquation()
    {
        const Scene scene = turnedScene();
        const CheckReference reference = makeTestCheckReference(scene);
        QVERIFY_OK(m_offscreen.renderer().setScene(scene));
        QStringList table{
            QStringLiteral("| made, slide's equation | found first | % | checked by |"),
            QStringLiteral("|---|---|---|---|")};
        QStringList failures;
        for (const MistakeVariant &made : allMistakeVariants()) {
            if (made.key == ShaderMistake::NegativeLight
                || made.key == ShaderMistake::BackfaceSpecular || made.key == ShaderMistake::Gouraud
                || made.key == ShaderMistake::PerFace)
                continue; // about the guard itself, or a shader of its own
            CheckReport report;
            const QString failure = checkMistake(withMistake(made, PhongEquation::Slide), reference,
                                                 made, std::nullopt, false, report);
            if (!failure.isEmpty())
                failures << failure;
            if (report.diagnosis.findings.empty())
                continue;
            const MistakeFinding &top = report.diagnosis.findings.front();
            table << QStringLiteral("| %1 | %2 | %3 | %4 |")
                         .arg(mistakeVariantName(made), shaderMistakeKey(top.key))
                         .arg(qRound(100.0 * top.confidence))
                         .arg(phongEquationKey(report.equation));
        }
        QVERIFY_OK(m_offscreen.renderer().setScene(m_scene));
        qInfo("mistakes made in the slide's equation, check scene turned:\n%s",
              qPrintable(table.join(QLatin1Char('\n'))));
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join(QLatin1Char('\n'))));
    }

    // The slide's equation taken literally (no N·L guard on the highlight)
    // passes by default and is named; demanding the guarded one fails it.
    void slideEquationPassesByDefault()
    {
        const ShaderPair slide = withMistake(ShaderMistake::BackfaceSpecular);
        const RgbImage image = toRgbImage(render(slide.vertex, slide.fragment));
        const CheckReport byDefault = checkRender(image, m_reference);
        QVERIFY2(byDefault.passed(), qPrintable(checkSummary(byDefault)));
        QCOMPARE(byDefault.equation, PhongEquation::Slide);
        const CheckReport guarded =
            checkRender(image, m_reference, kDefaultCheckToleranceSteps, PhongEquation::Guarded);
        QVERIFY(!guarded.passed());
        QCOMPARE(guarded.diagnosis.findings.front().key, ShaderMistake::BackfaceSpecular);
        const ShaderPair shipped = shippedPhong();
        const CheckReport asSlide =
            checkRender(toRgbImage(render(shipped.vertex, shipped.fragment)), m_reference,
                        kDefaultCheckToleranceSteps, PhongEquation::Slide);
        QVERIFY(!asSlide.passed());
        QCOMPARE(asSlide.diagnosis.findings.front().key, ShaderMistake::BackfaceSpecular);
    }

private:
    // The check scene seen from a camera that turns (so that M and MV, MV
    // and its transpose, a light moved with w = 0 and one left in world
    // coordinates all differ), with a second light whose c1 < 1 (so that
    // f_att needs its min(..., 1)).
    Scene turnedScene() const
    {
        Scene scene = m_scene;
        scene.camera.eye = glm::dvec3(2.2, 1.4, 3.4);
        scene.lights[1].attenuation = glm::dvec3(0.6, 0.0, 0.0); // light 0 keeps c2 > 0
        return scene;
    }

    // Renders `shaders`, checks them, and says what went wrong, if anything:
    // `made` must be found, named first (its key, or beside the key) and
    // explaining at least half the difference, and alone in first place
    // where `alone` asks. Empty when all holds; `report` gets the report.
    QString checkMistake(const ShaderPair &shaders, const CheckReference &reference,
                         MistakeVariant made, std::optional<PhongEquation> demanded, bool alone,
                         CheckReport &report)
    {
        const QString name = mistakeVariantName(made);
        report = checkRender(toRgbImage(render(shaders.vertex, shaders.fragment)), reference,
                             kDefaultCheckToleranceSteps, demanded);
        if (report.passed() || report.diagnosis.findings.empty())
            return name + QStringLiteral(": ") + checkSummary(report);
        const MistakeFinding &top = report.diagnosis.findings.front();
        const bool named = top.key == made.key
            || std::find(top.also.begin(), top.also.end(), made.key) != top.also.end();
        const bool first = report.diagnosis.findings.size() < 2
            || report.diagnosis.findings[1].confidence < top.confidence;
        if (!named || top.confidence < kExplainedConfidence || (alone && !first))
            return name + QStringLiteral(": ") + checkSummary(report);
        return {};
    }

    QImage render(const ShaderSource &vertex, const ShaderSource &fragment)
    {
        return toQImage(
            drawPair(m_offscreen, {vertex, fragment}, QSize(kCheckWidth, kCheckHeight)));
    }

    Scene m_scene;
    CheckReference m_reference;
    OffscreenRenderer m_offscreen;
};

QTEST_MAIN(TestCheckMistakes)
#include "tst_checkmistakes.moc"
