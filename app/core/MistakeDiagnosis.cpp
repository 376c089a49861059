#include "MistakeDiagnosis.h"

#include <algorithm>
#include <cstdlib>

namespace phonglab {

namespace {

// Images as rows of 0xffRRGGBB, so pixels are compared without QImage::pixel().
QImage rgb32(const QImage &image)
{
    return image.convertToFormat(QImage::Format_RGB32);
}

const QRgb *pixels(const QImage &image)
{
    return reinterpret_cast<const QRgb *>(image.constBits());
}

bool within(QRgb a, QRgb b, int steps)
{
    return std::abs(qRed(a) - qRed(b)) <= steps && std::abs(qGreen(a) - qGreen(b)) <= steps
        && std::abs(qBlue(a) - qBlue(b)) <= steps;
}

// Pixel i of a tightly packed RGB32 image (bytesPerLine == 4·width for
// every width: RGB32 rows need no padding).
QRgb at(const QImage &image, std::size_t i)
{
    return pixels(image)[i];
}

// The compared pixels where `image` is off `exact` by more than the tolerance.
std::vector<std::uint8_t> differing(const QImage &image, const QImage &exact, const std::vector<std::uint8_t> &compared,
                                    int steps)
{
    std::vector<std::uint8_t> out(compared.size(), 0);
    for (std::size_t i = 0; i < compared.size(); ++i)
        out[i] = compared[i] && !within(at(image, i), at(exact, i), steps);
    return out;
}

bool sameImage(const QImage &a, const QImage &b, const std::vector<std::uint8_t> &compared)
{
    for (std::size_t i = 0; i < compared.size(); ++i)
        if (compared[i] && at(a, i) != at(b, i))
            return false;
    return true;
}

} // namespace

bool MistakeDiagnosis::unexplained() const
{
    return differingPixels > 0 && (findings.empty() || findings.front().confidence < kExplainedConfidence);
}

MistakeDiagnosis diagnoseMistakes(const QImage &yours, const ReferenceImage &exact,
                                  const std::vector<std::pair<ShaderMistake, ReferenceImage>> &mistaken,
                                  const std::vector<std::uint8_t> &compared, int toleranceSteps,
                                  const glm::dvec3 &background)
{
    MistakeImages images;
    for (const auto &[mistake, reference] : mistaken)
        images.emplace_back(mistake, reference.toImage(background));
    return diagnoseMistakes(yours, exact.toImage(background), images, compared, toleranceSteps);
}

MistakeDiagnosis diagnoseMistakes(const QImage &yours, const QImage &exact, const MistakeImages &mistaken,
                                  const std::vector<std::uint8_t> &compared, int toleranceSteps)
{
    MistakeDiagnosis diagnosis;
    const std::size_t pixelCount = std::size_t(exact.width()) * std::size_t(exact.height());
    const bool sizesAgree = yours.size() == exact.size() && compared.size() == pixelCount
        && std::all_of(mistaken.begin(), mistaken.end(),
                       [&](const auto &m) { return m.second.size() == exact.size(); });
    if (!sizesAgree) {
        // Nothing to compare pixel by pixel: every compared pixel differs.
        diagnosis.differingPixels = std::count(compared.begin(), compared.end(), std::uint8_t(1));
        return diagnosis;
    }
    const QImage exactImage = rgb32(exact);
    const QImage user = rgb32(yours);
    const std::vector<std::uint8_t> userDiffers = differing(user, exactImage, compared, toleranceSteps);
    diagnosis.differingPixels = std::count(userDiffers.begin(), userDiffers.end(), std::uint8_t(1));

    // Mistakes in ShaderMistake's order, so the first of a group of equal
    // images is the one named.
    MistakeImages images;
    for (const auto &[mistake, image] : mistaken)
        images.emplace_back(mistake, rgb32(image));
    std::sort(images.begin(), images.end(), [](const auto &a, const auto &b) { return a.first < b.first; });

    std::vector<bool> grouped(images.size(), false);
    for (std::size_t m = 0; m < images.size(); ++m) {
        if (grouped[m])
            continue;
        const QImage &image = images[m].second;
        const std::vector<std::uint8_t> mistakeDiffers = differing(image, exactImage, compared, toleranceSteps);
        if (std::none_of(mistakeDiffers.begin(), mistakeDiffers.end(), [](std::uint8_t d) { return d != 0; })) {
            diagnosis.undetectable.push_back(images[m].first);
            continue;
        }
        MistakeFinding finding;
        finding.key = images[m].first;
        for (std::size_t other = m + 1; other < images.size(); ++other) {
            if (!grouped[other] && sameImage(image, images[other].second, compared)) {
                grouped[other] = true;
                finding.also.push_back(images[other].first);
            }
        }
        if (diagnosis.differingPixels == 0)
            continue;
        // Over the pixels where the render or the mistake differs from the
        // exact image: how many the mistake's image matches.
        qint64 either = 0, explained = 0;
        for (std::size_t i = 0; i < compared.size(); ++i) {
            if (!userDiffers[i] && !mistakeDiffers[i])
                continue;
            ++either;
            explained += within(at(user, i), at(image, i), toleranceSteps) ? 1 : 0;
        }
        finding.confidence = double(explained) / double(either);
        if (finding.confidence >= kMinListedConfidence)
            diagnosis.findings.push_back(std::move(finding));
    }
    std::stable_sort(diagnosis.findings.begin(), diagnosis.findings.end(),
                     [](const MistakeFinding &a, const MistakeFinding &b) { return a.confidence > b.confidence; });
    return diagnosis;
}

} // namespace phonglab
