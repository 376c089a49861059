#include "core/check/MistakeSets.h"

#include <QStringList>
#include <algorithm>

namespace phonglab {

namespace {

// Each step shades this many sets for real: those whose estimate comes
// closest.
constexpr std::size_t kShadedPerStep = 3;
// Estimates are made on at most this many compared pixels, spread evenly:
// enough to rank sets, and the same cost at every image size.
constexpr std::size_t kEstimateSamples = 16384;

bool combinable(ShaderMistake key)
{
    return key != ShaderMistake::Gouraud && key != ShaderMistake::PerFace;
}

// `set` with `v` in it: in place of another form of its key, or added.
std::vector<MistakeVariant> withVariant(std::vector<MistakeVariant> set, MistakeVariant v)
{
    for (MistakeVariant &member : set)
        if (member.key == v.key) {
            member = v;
            return set;
        }
    set.push_back(v);
    return set;
}

// The squared channel differences between the render and `image`, summed
// over `pixels`. What the search minimises: a term another one cancels in
// places (no ambient, no attenuation) still takes its share off it, where
// the fraction of pixels it matches says nothing yet.
double distance(const RgbImage &yours, const RgbImage &image,
                const std::vector<std::size_t> &pixels)
{
    double sum = 0.0;
    for (std::size_t i : pixels)
        for (int c = 0; c < 3; ++c) {
            const int d = int(yours.pixel(i)[c]) - int(image.pixel(i)[c]);
            sum += double(d * d);
        }
    return sum;
}

// Sets estimated without shading: a set with one or two more mistakes looks
// like the set's image with each mistake's own change from the exact image
// added (exact where the terms a mistake changes add up, close where they
// scale each other), on a sample of the pixels.
class Estimator
{
public:
    Estimator(const RgbImage &yours, const RgbImage &exact, std::vector<std::size_t> samples)
        : m_yours(yours)
        , m_exact(exact)
        , m_samples(std::move(samples))
    {
    }

    // The change `image` makes to the exact image at each sample.
    std::vector<int> changeOf(const RgbImage &image) const
    {
        std::vector<int> out;
        out.reserve(3 * m_samples.size());
        for (std::size_t i : m_samples)
            for (int c = 0; c < 3; ++c)
                out.push_back(int(image.pixel(i)[c]) - int(m_exact.pixel(i)[c]));
        return out;
    }

    void setBase(const RgbImage &set) { m_base = changeOf(set); }

    // The distance of the base set with the changes `a` (and `b`) added.
    double distanceWith(const std::vector<int> &a, const std::vector<int> *b = nullptr) const
    {
        double sum = 0.0;
        for (std::size_t s = 0; s < m_samples.size(); ++s)
            for (int c = 0; c < 3; ++c) {
                const std::size_t k = 3 * s + std::size_t(c);
                const int exact = m_exact.pixel(m_samples[s])[c];
                const int value = std::clamp(exact + m_base[k] + a[k] + (b ? (*b)[k] : 0), 0, 255);
                const int d = int(m_yours.pixel(m_samples[s])[c]) - value;
                sum += double(d * d);
            }
        return sum;
    }

private:
    const RgbImage &m_yours;
    const RgbImage &m_exact;
    std::vector<std::size_t> m_samples;
    std::vector<int> m_base;
};

std::vector<std::size_t> comparedPixels(const std::vector<std::uint8_t> &compared)
{
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < compared.size(); ++i)
        if (compared[i])
            out.push_back(i);
    return out;
}

std::vector<std::size_t> evenSample(const std::vector<std::size_t> &pixels, std::size_t most)
{
    if (pixels.size() <= most)
        return pixels;
    std::vector<std::size_t> out;
    out.reserve(most);
    for (std::size_t k = 0; k < most; ++k)
        out.push_back(pixels[k * pixels.size() / most]);
    return out;
}

struct Candidate {
    MistakeVariant variant;
    const RgbImage *image;
    std::vector<int> change;
};

struct Option {
    double estimate;
    std::vector<MistakeVariant> set;
};

// The sets one step away from `set`: one mistake added or put in place of
// another form of its key, or two added (two terms that cancel each other
// in places, no ambient and no attenuation, show only together), the
// closest first.
std::vector<Option> nextOptions(const std::vector<MistakeVariant> &set,
                                const std::vector<Candidate> &candidates, const Estimator &estimate)
{
    std::vector<Option> out;
    const auto add = [&](double e, std::vector<MistakeVariant> tried) {
        if (tried != set && int(tried.size()) <= kMaxMistakesTogether)
            out.push_back({e, std::move(tried)});
    };
    for (std::size_t a = 0; a < candidates.size(); ++a) {
        const Candidate &ca = candidates[a];
        add(estimate.distanceWith(ca.change), withVariant(set, ca.variant));
        const bool aNew = withVariant(set, ca.variant).size() > set.size();
        for (std::size_t b = a + 1; aNew && b < candidates.size(); ++b) {
            const Candidate &cb = candidates[b];
            if (cb.variant.key == ca.variant.key
                || withVariant(set, cb.variant).size() == set.size())
                continue;
            add(estimate.distanceWith(ca.change, &cb.change),
                withVariant(withVariant(set, ca.variant), cb.variant));
        }
    }
    // Stable: of two sets that look the same, the one of the earlier
    // mistakes (ShaderMistake's order) is named, as a single finding is.
    std::stable_sort(out.begin(), out.end(),
                     [](const Option &x, const Option &y) { return x.estimate < y.estimate; });
    if (out.size() > kShadedPerStep)
        out.resize(kShadedPerStep);
    return out;
}

// The mistakes that can join a set, and the one whose image comes closest
// (none: no mistake comes closer than the exact image).
struct FirstMistake {
    std::vector<Candidate> candidates;
    const RgbImage *image = nullptr;
    MistakeVariant variant;
    double distance = 0.0;
};

FirstMistake firstMistake(const RgbImage &yours, const RgbImage &exact,
                          const MistakeImages &singles, const std::vector<std::uint8_t> &compared,
                          const std::vector<std::size_t> &pixels, const Estimator &estimate)
{
    FirstMistake first;
    first.distance = distance(yours, exact, pixels);
    for (const auto &[variant, image] : singles) {
        // A mistake that changes nothing here cannot be told in a set either.
        if (!combinable(variant.key) || !image.sameSize(exact)
            || differing(image, exact, compared, 0) == std::vector<std::uint8_t>(compared.size()))
            continue;
        first.candidates.push_back({variant, &image, estimate.changeOf(image)});
        if (const double d = distance(yours, image, pixels); d < first.distance) {
            first.image = &image;
            first.variant = variant;
            first.distance = d;
        }
    }
    return first;
}

// A set with its image and that image's distance from the render.
struct ShadedSet {
    MistakeSet set;
    RgbImage image;
    double distance = 0.0;
};

// How the search shades a set and measures it against the render.
struct SetShading {
    const RgbImage &yours;
    const std::vector<std::size_t> &pixels;
    const ShadeMistakes &shade;
};

// Of the sets one step from `current`, the one that shades closest, if any
// comes closer than `current` (else an empty set).
ShadedSet closestNextSet(const ShadedSet &current, const std::vector<Candidate> &candidates,
                         const Estimator &estimate, const SetShading &s)
{
    ShadedSet best;
    best.distance = current.distance;
    for (Option &option : nextOptions(current.set.variants, candidates, estimate)) {
        RgbImage image = s.shade(option.set);
        if (const double d = distance(s.yours, image, s.pixels); d < best.distance) {
            best.set = {std::move(option.set), 0.0};
            best.image = std::move(image);
            best.distance = d;
        }
    }
    return best;
}

// Two added where one does as well: the one (a mistake must earn its
// place in the set).
void preferOneAdded(ShadedSet &best, const std::vector<MistakeVariant> &current,
                    const SetShading &s)
{
    for (std::size_t k = best.set.variants.size() - 2; k < best.set.variants.size(); ++k) {
        std::vector<MistakeVariant> one = current;
        one.push_back(best.set.variants[k]);
        RgbImage image = s.shade(one);
        if (const double d = distance(s.yours, image, s.pixels);
            d <= best.distance * (1.0 + kSetDistanceCut / 10.0)) {
            best.set.variants = std::move(one);
            best.image = std::move(image);
            best.distance = d;
            break;
        }
    }
}

} // namespace

MistakeSet findMistakeSet(const RgbImage &yours, const RgbImage &exact,
                          const MistakeImages &singles, const std::vector<std::uint8_t> &compared,
                          int toleranceSteps, const ShadeMistakes &shade)
{
    if (!yours.sameSize(exact) || compared.size() != exact.pixelCount())
        return {};
    const std::vector<std::uint8_t> yoursDiffers =
        differing(yours, exact, compared, toleranceSteps);
    const auto explains = [&](const RgbImage &image) {
        return explainedFraction(yours, yoursDiffers, image,
                                 differing(image, exact, compared, toleranceSteps), compared,
                                 toleranceSteps);
    };
    const std::vector<std::size_t> pixels = comparedPixels(compared);
    Estimator estimate(yours, exact, evenSample(pixels, kEstimateSamples));

    // The set starts with the mistake whose image comes closest.
    const FirstMistake first = firstMistake(yours, exact, singles, compared, pixels, estimate);
    if (!first.image)
        return {};
    ShadedSet current{{{first.variant}, explains(*first.image)}, *first.image, first.distance};
    const SetShading shading{yours, pixels, shade};
    // Each step adds a mistake or two, or puts another form of one in its
    // place, while that takes kSetDistanceCut off the distance.
    for (int step = 0; step < 2 * kMaxMistakesTogether && current.set.explains < kSetExplains;
         ++step) {
        estimate.setBase(current.image);
        ShadedSet best = closestNextSet(current, first.candidates, estimate, shading);
        if (best.set.variants.empty() || best.distance > (1.0 - kSetDistanceCut) * current.distance)
            break;
        if (best.set.variants.size() == current.set.variants.size() + 2)
            preferOneAdded(best, current.set.variants, shading);
        best.set.explains = explains(best.image);
        current = std::move(best);
    }
    MistakeSet set = std::move(current.set);
    std::sort(set.variants.begin(), set.variants.end());
    set.beyondLimit =
        int(set.variants.size()) >= kMaxMistakesTogether && set.explains < kSetWellExplained;
    return set;
}

QString mistakeSetName(const MistakeSet &set)
{
    QStringList names;
    for (MistakeVariant v : set.variants)
        names << mistakeVariantName(v);
    return names.join(QStringLiteral(" + "));
}

QString mistakeSetKeys(const MistakeSet &set)
{
    QStringList keys;
    for (MistakeVariant v : set.variants)
        keys << shaderMistakeKey(v.key);
    return keys.join(QLatin1Char(' '));
}

} // namespace phonglab
