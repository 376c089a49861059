#include "MistakeDiagnosis.h"

#include <algorithm>
#include <cstdlib>

namespace phonglab {

namespace {

bool within(QRgb a, QRgb b, int steps)
{
    return std::abs(qRed(a) - qRed(b)) <= steps && std::abs(qGreen(a) - qGreen(b)) <= steps
        && std::abs(qBlue(a) - qBlue(b)) <= steps;
}

// The compared pixels where `image` is off `exact` by more than the tolerance.
std::vector<std::uint8_t> differing(const QImage &image, const QImage &exact, const std::vector<std::uint8_t> &compared,
                                    int steps)
{
    std::vector<std::uint8_t> out(compared.size(), 0);
    const int w = exact.width();
    for (std::size_t i = 0; i < compared.size(); ++i) {
        const int x = int(i % std::size_t(w)), y = int(i / std::size_t(w));
        out[i] = compared[i] && !within(image.pixel(x, y), exact.pixel(x, y), steps);
    }
    return out;
}

bool sameImage(const QImage &a, const QImage &b, const std::vector<std::uint8_t> &compared)
{
    const int w = a.width();
    for (std::size_t i = 0; i < compared.size(); ++i)
        if (compared[i] && a.pixel(int(i % std::size_t(w)), int(i / std::size_t(w)))
                               != b.pixel(int(i % std::size_t(w)), int(i / std::size_t(w))))
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
    MistakeDiagnosis diagnosis;
    if (yours.size() != QSize(exact.width, exact.height) || compared.size() != exact.color.size()) {
        // Nothing to compare pixel by pixel: every compared pixel differs.
        diagnosis.differingPixels = std::count(compared.begin(), compared.end(), std::uint8_t(1));
        return diagnosis;
    }
    const QImage exactImage = exact.toImage(background);
    const QImage user = yours.convertToFormat(QImage::Format_RGB32);
    const std::vector<std::uint8_t> userDiffers = differing(user, exactImage, compared, toleranceSteps);
    diagnosis.differingPixels = std::count(userDiffers.begin(), userDiffers.end(), std::uint8_t(1));

    // Mistakes in ShaderMistake's order, so the first of a group of equal
    // images is the one named.
    std::vector<std::pair<ShaderMistake, QImage>> images;
    for (const auto &[mistake, reference] : mistaken)
        images.emplace_back(mistake, reference.toImage(background));
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
        const int w = exactImage.width();
        for (std::size_t i = 0; i < compared.size(); ++i) {
            if (!userDiffers[i] && !mistakeDiffers[i])
                continue;
            ++either;
            const int x = int(i % std::size_t(w)), y = int(i / std::size_t(w));
            explained += within(user.pixel(x, y), image.pixel(x, y), toleranceSteps) ? 1 : 0;
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
