// What a check shades beyond its reference is shaded once per reference,
// however many renders and threads ask (core/check/ShadedMistakes): the
// cache `grade` relies on to check a class's rows in parallel.
#include "core/check/ShadedMistakes.h"

#include <QtTest>

#include <atomic>
#include <thread>

using namespace phonglab;

namespace {

RgbImage filled(std::uint8_t value)
{
    RgbImage image(4, 2);
    std::fill(image.bytes.begin(), image.bytes.end(), value);
    return image;
}

std::vector<MistakeVariant> setOf(ShaderMistake key)
{
    MistakeVariant variant;
    variant.key = key;
    return {variant};
}

} // namespace

class TestShadedMistakes : public QObject
{
    Q_OBJECT

private slots:
    void eachSetIsShadedOncePerEquation();
    void threadsShareOneShading();
    void pastTheCapSetsAreShadedEachTime();
    void slideMistakesAreShadedOnce();
};

void TestShadedMistakes::eachSetIsShadedOncePerEquation()
{
    ShadedMistakes cache;
    int shaded = 0;
    const auto shade = [&] {
        ++shaded;
        return filled(std::uint8_t(shaded));
    };
    const auto set = setOf(ShaderMistake::ReflectIncident);
    const RgbImage first = cache.setImage(PhongEquation::Guarded, set, shade);
    const RgbImage again = cache.setImage(PhongEquation::Guarded, set, shade);
    QCOMPARE(shaded, 1);
    QVERIFY(first.bytes == again.bytes);
    // The slide's equation and another set are other images.
    cache.setImage(PhongEquation::Slide, set, shade);
    cache.setImage(PhongEquation::Guarded, setOf(ShaderMistake::HalfwayVector), shade);
    QCOMPARE(shaded, 3);
}

void TestShadedMistakes::threadsShareOneShading()
{
    ShadedMistakes cache;
    std::atomic<int> shaded = 0;
    const auto set = setOf(ShaderMistake::ReflectIncident);
    // The first caller keeps its image; a second that shaded at the same time
    // gets identical pixels, and every later caller the kept one.
    std::vector<std::thread> threads;
    std::vector<RgbImage> got(8);
    for (std::size_t t = 0; t < got.size(); ++t)
        threads.emplace_back([&, t] {
            got[t] = cache.setImage(PhongEquation::Guarded, set, [&] {
                ++shaded;
                return filled(7);
            });
        });
    for (std::thread &t : threads)
        t.join();
    for (const RgbImage &image : got)
        QVERIFY(image.bytes == filled(7).bytes);
    const int before = shaded;
    cache.setImage(PhongEquation::Guarded, set, [&] {
        ++shaded;
        return filled(7);
    });
    QCOMPARE(shaded.load(), before);
}

void TestShadedMistakes::pastTheCapSetsAreShadedEachTime()
{
    ShadedMistakes cache;
    int shaded = 0;
    const auto shade = [&] {
        ++shaded;
        return filled(1);
    };
    // Sets of every pair of distinct mistakes: more than the cap keeps.
    const std::vector<MistakeVariant> all = allMistakeVariants();
    std::vector<std::vector<MistakeVariant>> sets;
    for (std::size_t a = 0; a < all.size() && sets.size() <= ShadedMistakes::kMaxKeptSets; ++a)
        for (std::size_t b = a + 1; b < all.size() && sets.size() <= ShadedMistakes::kMaxKeptSets;
             ++b)
            sets.push_back({all[a], all[b]});
    QVERIFY(sets.size() > ShadedMistakes::kMaxKeptSets);
    for (const auto &set : sets)
        cache.setImage(PhongEquation::Guarded, set, shade);
    QCOMPARE(shaded, int(sets.size()));
    cache.setImage(PhongEquation::Guarded, sets.front(), shade); // kept
    QCOMPARE(shaded, int(sets.size()));
    cache.setImage(PhongEquation::Guarded, sets.back(), shade); // past the cap: shaded again
    QCOMPARE(shaded, int(sets.size()) + 1);
}

void TestShadedMistakes::slideMistakesAreShadedOnce()
{
    ShadedMistakes cache;
    int shaded = 0;
    const auto shadeAll = [&] {
        ++shaded;
        return MistakeImages{{setOf(ShaderMistake::ReflectIncident).front(), filled(3)}};
    };
    const MistakeImages &first = cache.slideMistakes(shadeAll);
    const MistakeImages &again = cache.slideMistakes(shadeAll);
    QCOMPARE(shaded, 1);
    QCOMPARE(&first, &again);
    QCOMPARE(first.size(), std::size_t(1));
}

QTEST_MAIN(TestShadedMistakes)
#include "tst_shadedmistakes.moc"
