#include "core/check/MistakeDiagnosis.h"

#include <algorithm>
#include <cstdlib>

namespace phonglab {

bool withinSteps(const std::uint8_t *a, const std::uint8_t *b, int steps)
{
    return std::abs(a[0] - b[0]) <= steps && std::abs(a[1] - b[1]) <= steps
        && std::abs(a[2] - b[2]) <= steps;
}

std::vector<std::uint8_t> differing(const RgbImage &image, const RgbImage &exact,
                                    const std::vector<std::uint8_t> &compared, int steps)
{
    std::vector<std::uint8_t> out(compared.size(), 0);
    for (std::size_t i = 0; i < compared.size(); ++i)
        out[i] = compared[i] && !withinSteps(image.pixel(i), exact.pixel(i), steps);
    return out;
}

double explainedFraction(const RgbImage &yours, const std::vector<std::uint8_t> &yoursDiffers,
                         const RgbImage &mistaken, const std::vector<std::uint8_t> &mistakeDiffers,
                         const std::vector<std::uint8_t> &compared, int steps)
{
    qint64 either = 0, explained = 0;
    for (std::size_t i = 0; i < compared.size(); ++i) {
        if (!yoursDiffers[i] && !mistakeDiffers[i])
            continue;
        ++either;
        explained += withinSteps(yours.pixel(i), mistaken.pixel(i), steps) ? 1 : 0;
    }
    return either > 0 ? double(explained) / double(either) : 0.0;
}

namespace {

bool equal(const std::uint8_t *a, const std::uint8_t *b)
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

bool sameImage(const RgbImage &a, const RgbImage &b, const std::vector<std::uint8_t> &compared)
{
    for (std::size_t i = 0; i < compared.size(); ++i)
        if (compared[i] && !equal(a.pixel(i), b.pixel(i)))
            return false;
    return true;
}

// Best first, and one finding per key: its best form's. A key already named
// (as a finding's key or beside it) is not named again.
std::vector<MistakeFinding> bestFormOfEachKey(std::vector<MistakeFinding> findings)
{
    std::stable_sort(findings.begin(), findings.end(),
                     [](const MistakeFinding &a, const MistakeFinding &b) {
                         return a.confidence > b.confidence;
                     });
    std::vector<ShaderMistake> named;
    const auto isNamed = [&](ShaderMistake key) {
        return std::find(named.begin(), named.end(), key) != named.end();
    };
    std::vector<MistakeFinding> out;
    for (MistakeFinding &finding : findings) {
        if (isNamed(finding.key))
            continue;
        std::erase_if(finding.also, isNamed);
        named.push_back(finding.key);
        named.insert(named.end(), finding.also.begin(), finding.also.end());
        out.push_back(std::move(finding));
    }
    return out;
}

using OrderedImages = std::vector<std::pair<MistakeVariant, const RgbImage *>>;

// Mistakes in ShaderMistake's order, so the first of a group of equal
// images is the one named.
OrderedImages inMistakeOrder(const MistakeImages &mistaken)
{
    OrderedImages images;
    for (const auto &[mistake, image] : mistaken)
        images.emplace_back(mistake, &image);
    std::sort(images.begin(), images.end(),
              [](const auto &a, const auto &b) { return a.first < b.first; });
    return images;
}

// Which mistakes are already in a group of equal images, and the keys with
// a form that shows here.
struct ImageGroups {
    std::vector<bool> grouped;
    std::vector<ShaderMistake> detectable;
};

// Groups the later mistakes whose image is image `m`'s with it: their keys
// go beside `finding`'s.
void groupSameImages(ImageGroups &groups, const OrderedImages &images, std::size_t m,
                     const std::vector<std::uint8_t> &compared, MistakeFinding &finding)
{
    const RgbImage &image = *images[m].second;
    for (std::size_t other = m + 1; other < images.size(); ++other) {
        if (!groups.grouped[other] && sameImage(image, *images[other].second, compared)) {
            groups.grouped[other] = true;
            const ShaderMistake key = images[other].first.key;
            groups.detectable.push_back(key);
            if (key != finding.key
                && std::find(finding.also.begin(), finding.also.end(), key) == finding.also.end())
                finding.also.push_back(key);
        }
    }
}

// The keys none of whose forms shows here, each once.
std::vector<ShaderMistake> undetectableKeys(const OrderedImages &images,
                                            const std::vector<ShaderMistake> &detectable)
{
    std::vector<ShaderMistake> undetectable;
    for (const auto &[variant, image] : images)
        if (std::find(detectable.begin(), detectable.end(), variant.key) == detectable.end()
            && std::find(undetectable.begin(), undetectable.end(), variant.key)
                == undetectable.end())
            undetectable.push_back(variant.key);
    return undetectable;
}

} // namespace

bool MistakeDiagnosis::unexplained() const
{
    return differingPixels > 0
        && (findings.empty()
            || (findings.front().confidence < kExplainedConfidence && !findings.front().fromCode))
        && !togetherExplains();
}

bool MistakeDiagnosis::togetherExplains() const
{
    return !together.variants.empty() && together.explains >= kExplainedConfidence;
}

void nameGouraudFromCode(MistakeDiagnosis &diagnosis)
{
    auto &found = diagnosis.findings;
    const auto it = std::find_if(found.begin(), found.end(), [](const MistakeFinding &f) {
        return f.key == ShaderMistake::Gouraud;
    });
    MistakeFinding gouraud{ShaderMistake::Gouraud, 0, {}, 0.0, true};
    if (it != found.end()) {
        gouraud = *it;
        gouraud.fromCode = true;
        found.erase(it);
    }
    found.insert(found.begin(), gouraud);
    diagnosis.together = {};
}

MistakeDiagnosis diagnoseMistakes(
    const RgbImage &yours, const ReferenceImage &exact,
    const std::vector<std::pair<MistakeVariant, ReferenceImage>> &mistaken,
    const std::vector<std::uint8_t> &compared, int toleranceSteps, const glm::dvec3 &background)
{
    MistakeImages images;
    for (const auto &[mistake, reference] : mistaken)
        images.emplace_back(mistake, reference.toImage(background));
    return diagnoseMistakes(yours, exact.toImage(background), images, compared, toleranceSteps);
}

MistakeDiagnosis diagnoseMistakes(const RgbImage &yours, const RgbImage &exact,
                                  const MistakeImages &mistaken,
                                  const std::vector<std::uint8_t> &compared, int toleranceSteps)
{
    MistakeDiagnosis diagnosis;
    const bool sizesAgree = yours.sameSize(exact) && compared.size() == exact.pixelCount()
        && std::all_of(mistaken.begin(), mistaken.end(),
                       [&](const auto &m) { return m.second.sameSize(exact); });
    if (!sizesAgree) {
        // Nothing to compare pixel by pixel: every compared pixel differs.
        diagnosis.differingPixels = std::count(compared.begin(), compared.end(), std::uint8_t(1));
        return diagnosis;
    }
    const std::vector<std::uint8_t> userDiffers = differing(yours, exact, compared, toleranceSteps);
    diagnosis.differingPixels = std::count(userDiffers.begin(), userDiffers.end(), std::uint8_t(1));

    const OrderedImages images = inMistakeOrder(mistaken);
    ImageGroups groups{std::vector<bool>(images.size(), false), {}};
    std::vector<MistakeFinding> findings;
    for (std::size_t m = 0; m < images.size(); ++m) {
        if (groups.grouped[m])
            continue;
        const RgbImage &image = *images[m].second;
        const std::vector<std::uint8_t> mistakeDiffers =
            differing(image, exact, compared, toleranceSteps);
        if (std::none_of(mistakeDiffers.begin(), mistakeDiffers.end(),
                         [](std::uint8_t d) { return d != 0; }))
            continue;
        MistakeFinding finding;
        finding.key = images[m].first.key;
        finding.form = images[m].first.form;
        groups.detectable.push_back(finding.key);
        groupSameImages(groups, images, m, compared, finding);
        if (diagnosis.differingPixels == 0)
            continue;
        finding.confidence =
            explainedFraction(yours, userDiffers, image, mistakeDiffers, compared, toleranceSteps);
        if (finding.confidence >= kMinListedConfidence)
            findings.push_back(std::move(finding));
    }
    diagnosis.undetectable = undetectableKeys(images, groups.detectable);
    diagnosis.findings = bestFormOfEachKey(std::move(findings));
    return diagnosis;
}

} // namespace phonglab
