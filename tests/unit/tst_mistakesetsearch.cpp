// The smallest set of mistakes that explains a render (core/check/MistakeSets),
// on the CPU reference's own images: a render made with two or three
// mistakes at once is explained by exactly that set; one made with one
// mistake by that mistake, with no combined image shaded at all; noise by
// no set that explains it.
#include "MistakeScenes.h"
#include "core/check/MistakeSets.h"
#include "core/reference/MeshRaycaster.h"

#include <QRandomGenerator>
#include <QTest>

using namespace phonglab;
using phonglab::test::mistakeScene;

Q_DECLARE_METATYPE(std::vector<MistakeVariant>)

namespace {

constexpr int kSize = 64;
constexpr int kDefaultTolerance = 2;
const glm::dvec3 kBackground(0.1);

RgbImage render(const Scene &s, const std::vector<MistakeVariant> &set)
{
    return raycastScene(s, kSize, kSize, ReferenceShader(ReferenceShading::Phong, set))
        ->toImage(kBackground);
}

struct Search {
    MistakeSet set;
    int shaded = 0; // combined images the search asked for
};

Search search(const Scene &s, const RgbImage &yours)
{
    const ReferenceImage exact = *raycastScene(s, kSize, kSize, ReferenceShading::Phong);
    MistakeImages singles;
    for (MistakeVariant v : allMistakeVariants())
        singles.emplace_back(v, render(s, {v}));
    Search out;
    out.set = findMistakeSet(yours, exact.toImage(kBackground), singles, exact.coverage,
                             kDefaultTolerance, [&](const std::vector<MistakeVariant> &set) {
                                 ++out.shaded;
                                 return render(s, set);
                             });
    return out;
}

QString keys(const std::vector<MistakeVariant> &set)
{
    return mistakeSetKeys({set, 0.0});
}

} // namespace

class TestMistakeSetSearch : public QObject
{
    Q_OBJECT

private slots:
    void severalMistakesAreNamedTogether_data()
    {
        using K = ShaderMistake;
        QTest::addColumn<std::vector<MistakeVariant>>("made");
        QTest::newRow("halfway-vector + attenuation")
            << std::vector<MistakeVariant>{{K::Attenuation, 0}, {K::HalfwayVector, 0}};
        QTest::newRow("ambient + halfway-vector")
            << std::vector<MistakeVariant>{{K::Ambient, 0}, {K::HalfwayVector, 0}};
        QTest::newRow("attenuation + ambient + halfway-vector") << std::vector<MistakeVariant>{
            {K::Attenuation, 0}, {K::Ambient, 0}, {K::HalfwayVector, 0}};
        QTest::newRow("negative-light + backface-specular")
            << std::vector<MistakeVariant>{{K::NegativeLight, 0}, {K::BackfaceSpecular, 0}};
        QTest::newRow("light-space + ambient per light") << std::vector<MistakeVariant>{
            {K::LightSpace, 0}, {K::Ambient, MistakeForm::AmbientPerLight}};
    }

    void severalMistakesAreNamedTogether()
    {
        QFETCH(std::vector<MistakeVariant>, made);
        const Scene s = mistakeScene();
        const Search found = search(s, render(s, made));
        QCOMPARE(keys(found.set.variants), keys(made));
        QCOMPARE(found.set.variants, made);
        QVERIFY2(found.set.explains >= kSetWellExplained,
                 qPrintable(QString::number(found.set.explains)));
    }

    void oneMistakeShadesNothingMore()
    {
        const Scene s = mistakeScene();
        const MistakeVariant made{ShaderMistake::ReflectIncident, 0};
        const Search found = search(s, render(s, {made}));
        QCOMPARE(found.set.variants, std::vector<MistakeVariant>{made});
        QCOMPARE(found.shaded, 0);
    }

    void noiseIsNotExplained()
    {
        const Scene s = mistakeScene();
        RgbImage yours = render(s, {});
        QRandomGenerator random(7);
        for (std::uint8_t &b : yours.bytes)
            b = std::uint8_t(random.bounded(256));
        const Search found = search(s, yours);
        QVERIFY2(found.set.explains < kExplainedConfidence, qPrintable(mistakeSetName(found.set)));
        QVERIFY(int(found.set.variants.size()) <= kMaxMistakesTogether);
    }
};

QTEST_GUILESS_MAIN(TestMistakeSetSearch)
#include "tst_mistakesetsearch.moc"
