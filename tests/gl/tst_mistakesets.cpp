// Real course code breaks several of the equation's rules at once. Every
// pair and every triple of halfway-vector, attenuation, ambient,
// light-space and backface-specular, made in the shipped Phong shaders
// (ShaderMutations.h), is named in full by the diagnosis' smallest set
// (`together`) on the check scene; one mistake alone keeps its one key, and
// the correct shader still passes. A member whose effect the others hide in
// this scene (the exact reference of the set differs from the one without
// it by no more than the tolerance) cannot be named by anything and is not
// required (here only light-space hides backface-specular's highlight); the
// table says where. backface-specular is a mistake only where the guarded
// equation is demanded (by default the slide's literal equation passes
// too), so a set holding it is checked with --equation guarded.
#include "CheckScene.h"
#include "ResultChecks.h"
#include "ShaderMutations.h"
#include "core/check/MistakeSets.h"
#include "core/reference/SceneHits.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/QtImages.h"

#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

const std::vector<ShaderMistake> kDeviations{
    ShaderMistake::HalfwayVector, ShaderMistake::Attenuation, ShaderMistake::Ambient,
    ShaderMistake::LightSpace, ShaderMistake::BackfaceSpecular};

// Every subset of `kDeviations` of `size`, in order.
std::vector<std::vector<MistakeVariant>> subsets(int size)
{
    std::vector<std::vector<MistakeVariant>> out;
    const int n = int(kDeviations.size());
    for (int mask = 0; mask < (1 << n); ++mask) {
        if (__builtin_popcount(unsigned(mask)) != size)
            continue;
        std::vector<MistakeVariant> set;
        for (int i = 0; i < n; ++i)
            if (mask & (1 << i))
                set.push_back({kDeviations[std::size_t(i)], 0});
        std::sort(set.begin(), set.end());
        out.push_back(set);
    }
    return out;
}

QString keysOf(const std::vector<MistakeVariant> &set)
{
    return mistakeSetKeys(MistakeSet{set, 0.0});
}

} // namespace

class TestMistakeSets : public QObject
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

    void correctShaderPasses()
    {
        const ShaderPair s = shippedPhong();
        const CheckReport report = checkRender(checkedImage(s), m_reference);
        QVERIFY2(report.passed(), qPrintable(checkSummary(report)));
        QVERIFY(report.diagnosis.together.variants.empty());
    }

    void oneMistakeKeepsItsOneKey()
    {
        for (ShaderMistake m : kDeviations) {
            const CheckReport report = check({{m, 0}});
            QVERIFY2(!report.passed(), qPrintable(shaderMistakeKey(m)));
            QCOMPARE(keysOf(report.diagnosis.together.variants), shaderMistakeKey(m));
            QCOMPARE(report.diagnosis.findings.front().key, m);
        }
    }

    void everyPairAndTripleIsNamedInFull()
    {
        QStringList table{QStringLiteral("| made | named together | explains |"),
                          QStringLiteral("|---|---|---|")};
        QStringList failures;
        for (int size : {2, 3}) {
            for (const std::vector<MistakeVariant> &made : subsets(size)) {
                const CheckReport report = check(made);
                const MistakeSet &found = report.diagnosis.together;
                const std::vector<MistakeVariant> shown = showing(made);
                table << QStringLiteral("| %1 | %2 | %3 % |%4")
                             .arg(keysOf(made), keysOf(found.variants))
                             .arg(qRound(100.0 * found.explains))
                             .arg(shown == made ? QString()
                                                : QStringLiteral(" hidden here: all but %1")
                                                      .arg(keysOf(shown)));
                // Named in full: every member that shows, and none that was
                // not made (one the others hide may still be named).
                const auto within = [](const std::vector<MistakeVariant> &part,
                                       const std::vector<MistakeVariant> &whole) {
                    return std::includes(whole.begin(), whole.end(), part.begin(), part.end());
                };
                if (report.passed() || !within(shown, found.variants)
                    || !within(found.variants, made) || found.explains < kExplainedConfidence)
                    failures << keysOf(made) + QStringLiteral(": ") + checkSummary(report);
                else if (found.variants.size() > 1
                         && !checkSummary(report).contains(QStringLiteral("mistakes together")))
                    failures << keysOf(made) + QStringLiteral(": the summary does not say it: ")
                            + checkSummary(report);
                // Only light-space hides another here: backface-specular's
                // highlight, the moved light no longer behind the surface.
                for (MistakeVariant m : made)
                    if (!within({m}, shown)
                        && !(m.key == ShaderMistake::BackfaceSpecular
                             && within({{ShaderMistake::LightSpace, 0}}, made)))
                        failures << keysOf(made)
                                + QStringLiteral(": %1 hidden").arg(shaderMistakeKey(m.key));
            }
        }
        qInfo("mistakes made together on assets/scenes/check.json, %dx%d:\n%s", kCheckWidth,
              kCheckHeight, qPrintable(table.join(QLatin1Char('\n'))));
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join(QLatin1Char('\n'))));
    }

private:
    // The members of `made` whose effect shows in this scene: each whose
    // removal changes the exact reference of the set by more than the
    // check's tolerance (what `undetectable` means for one mistake).
    std::vector<MistakeVariant> showing(const std::vector<MistakeVariant> &made)
    {
        const auto image = [&](const std::vector<MistakeVariant> &set) {
            return shadeSceneHits(m_reference.hits, m_reference.scene,
                                  ReferenceShader(ReferenceShading::Phong, set))
                .toImage(m_reference.background);
        };
        const RgbImage all = image(made);
        std::vector<MistakeVariant> out;
        for (MistakeVariant m : made) {
            std::vector<MistakeVariant> without = made;
            std::erase(without, m);
            const std::vector<std::uint8_t> changed =
                differing(image(without), all, m_reference.compared, kDefaultCheckToleranceSteps);
            if (std::count(changed.begin(), changed.end(), std::uint8_t(1)) > 0)
                out.push_back(m);
        }
        return out;
    }

    RgbImage checkedImage(const ShaderPair &s)
    {
        return drawPair(m_offscreen, s, QSize(kCheckWidth, kCheckHeight));
    }

    CheckReport check(const std::vector<MistakeVariant> &made)
    {
        const bool guardDemanded = std::any_of(made.begin(), made.end(), [](MistakeVariant v) {
            return v.key == ShaderMistake::BackfaceSpecular;
        });
        return checkRender(checkedImage(withMistakes(made)), m_reference,
                           kDefaultCheckToleranceSteps,
                           guardDemanded ? std::optional(PhongEquation::Guarded) : std::nullopt);
    }

    Scene m_scene;
    CheckReference m_reference;
    OffscreenRenderer m_offscreen;
};

QTEST_MAIN(TestMistakeSets)
#include "tst_mistakesets.moc"
