#include "ImageMetrics.h"
#include "core/support/Language.h"

#include "PhongReference.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>
#include <vector>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ImageMetricsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ImageMetrics)
};

namespace {

// Sums squared channel differences one pixel at a time and keeps the worst.
class ErrorAccumulator
{
public:
    void add(const uchar *a, const uchar *b, int x, int y)
    {
        for (int c = 0; c < 3; ++c) {
            const int diff = std::abs(int(a[c]) - int(b[c]));
            m_sumSquares += double(diff) * diff;
            if (diff > m_result.maxError) {
                m_result.maxError = diff;
                m_result.worstPixel = QPoint(x, y);
            }
        }
        ++m_result.pixelsCompared;
    }

    ImageComparison result() const
    {
        ImageComparison r = m_result;
        if (r.pixelsCompared == 0)
            return r; // nothing compared: psnr stays 0 so no check passes vacuously
        r.rmse = std::sqrt(m_sumSquares / (3.0 * double(r.pixelsCompared)));
        r.psnr = r.rmse == 0.0 ? std::numeric_limits<double>::infinity()
                               : 20.0 * std::log10(255.0 / r.rmse);
        return r;
    }

private:
    ImageComparison m_result;
    double m_sumSquares = 0;
};

bool sameSize(const RgbImage &rendered, const ReferenceImage &reference)
{
    return !rendered.isNull() && !reference.isNull() && rendered.width == reference.width
        && rendered.height == reference.height;
}

// 1 where a pixel's coverage differs from one of its 8 neighbours.
std::vector<std::uint8_t> silhouettePixels(const ReferenceImage &ref)
{
    std::vector<std::uint8_t> edge(ref.coverage.size(), 0);
    for (int y = 0; y < ref.height; ++y) {
        for (int x = 0; x < ref.width; ++x) {
            const bool here = ref.covered(x, y);
            for (int dy = -1; dy <= 1 && !edge[ref.index(x, y)]; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= ref.width || ny >= ref.height)
                        continue; // the image border is not a silhouette
                    if (ref.covered(nx, ny) != here) {
                        edge[ref.index(x, y)] = 1;
                        break;
                    }
                }
            }
        }
    }
    return edge;
}

// Dilates `mask` (width × height) by a (2r+1)² square, i.e. marks every pixel
// within Chebyshev distance r of a set pixel. Separable: a row pass then a
// column pass, each a sliding window count, so the cost does not grow with r.
std::vector<std::uint8_t> dilateSquare(const std::vector<std::uint8_t> &mask, int width, int height,
                                       int r)
{
    auto pass = [r](const std::vector<std::uint8_t> &in, int count, int length, auto at) {
        std::vector<std::uint8_t> out(in.size(), 0);
        for (int line = 0; line < count; ++line) {
            int inWindow = 0; // set pixels in [i - r, i + r]
            for (int i = 0; i < std::min(r, length); ++i)
                inWindow += in[at(line, i)];
            for (int i = 0; i < length; ++i) {
                if (i + r < length)
                    inWindow += in[at(line, i + r)];
                if (i - r - 1 >= 0)
                    inWindow -= in[at(line, i - r - 1)];
                out[at(line, i)] = inWindow > 0;
            }
        }
        return out;
    };
    const auto rowMajor = [width](int row, int x) { return std::size_t(row) * width + x; };
    const auto columnMajor = [width](int column, int y) { return std::size_t(y) * width + column; };
    return pass(pass(mask, height, width, rowMajor), width, height, columnMajor);
}

// 1 for the pixels compareWithReference() compares.
std::vector<std::uint8_t> comparedPixels(const ReferenceImage &reference, int bandPx)
{
    const std::vector<std::uint8_t> band = dilateSquare(
        silhouettePixels(reference), reference.width, reference.height, std::max(bandPx, 0));
    std::vector<std::uint8_t> compared(band.size(), 0);
    for (std::size_t i = 0; i < band.size(); ++i)
        compared[i] = reference.coverage[i] != 0 && !band[i];
    return compared;
}

void encodeReferencePixel(const ReferenceImage &reference, std::size_t i, uchar *out)
{
    const glm::dvec3 &I = reference.color[i];
    out[0] = uchar(encodeChannel(I.r));
    out[1] = uchar(encodeChannel(I.g));
    out[2] = uchar(encodeChannel(I.b));
}

void setColor(uchar *out, int r, int g, int b)
{
    out[0] = uchar(r);
    out[1] = uchar(g);
    out[2] = uchar(b);
}

void setHeatColor(uchar *out, int error)
{
    // Dark green at 0, yellow at 4/255, red at 8/255 and beyond.
    const double t = std::min(error, 8) / 8.0;
    if (error == 0)
        setColor(out, 0, 64, 0);
    else if (t <= 0.5)
        setColor(out, int(510 * t), 255, 0);
    else
        setColor(out, 255, int(510 * (1.0 - t)), 0);
}

} // namespace

QString ImageComparison::summary() const
{
    if (pixelsCompared == 0)
        return ImageMetricsWords::tr("no pixels compared");
    const QString psnrText =
        std::isinf(psnr) ? QStringLiteral("inf") : sentenceNumber(psnr, 'f', 2);
    return ImageMetricsWords::tr("PSNR %1 dB, RMSE %2, max %3/255 at (%4,%5), %6 px")
        .arg(psnrText)
        .arg(sentenceNumber(rmse, 'f', 2))
        .arg(maxError)
        .arg(worstPixel.x())
        .arg(worstPixel.y())
        .arg(pixelsCompared);
}

ImageComparison compareWithReference(const RgbImage &rendered, const ReferenceImage &reference,
                                     int bandPx)
{
    if (!sameSize(rendered, reference))
        return {};
    const std::vector<std::uint8_t> compared = comparedPixels(reference, bandPx);
    ErrorAccumulator errors;
    for (int y = 0; y < reference.height; ++y) {
        for (int x = 0; x < reference.width; ++x) {
            const std::size_t i = reference.index(x, y);
            if (!compared[i])
                continue;
            uchar expected[3];
            encodeReferencePixel(reference, i, expected);
            errors.add(rendered.pixel(i), expected, x, y);
        }
    }
    return errors.result();
}

BandComparison compareOutsideBand(const RgbImage &rendered, const ReferenceImage &reference,
                                  const glm::dvec3 &background, int bandPx,
                                  const std::vector<std::uint8_t> *mask)
{
    BandComparison out;
    if (!sameSize(rendered, reference) || (mask && mask->size() != reference.color.size()))
        return out;
    const std::vector<std::uint8_t> band = dilateSquare(
        silhouettePixels(reference), reference.width, reference.height, std::max(bandPx, 0));
    const uchar bg[3] = {uchar(encodeChannel(background.r)), uchar(encodeChannel(background.g)),
                         uchar(encodeChannel(background.b))};
    ErrorAccumulator errors;
    for (int y = 0; y < reference.height; ++y) {
        for (int x = 0; x < reference.width; ++x) {
            const std::size_t i = reference.index(x, y);
            if (band[i] || (mask && !(*mask)[i]))
                continue;
            const uchar *got = rendered.pixel(i);
            const bool renderCovers = got[0] != bg[0] || got[1] != bg[1] || got[2] != bg[2];
            const bool referenceCovers = reference.coverage[i] != 0;
            if (!referenceCovers && !renderCovers)
                continue;
            if (referenceCovers != renderCovers)
                ++out.coverageErrors;
            uchar expected[3];
            if (referenceCovers)
                encodeReferencePixel(reference, i, expected);
            else
                std::copy(bg, bg + 3, expected);
            errors.add(got, expected, x, y);
        }
    }
    out.error = errors.result();
    return out;
}

std::vector<std::uint8_t> occludingContourPixels(const ReferenceImage &reference,
                                                 double relativeJump)
{
    const int w = reference.width, h = reference.height;
    std::vector<std::uint8_t> contour(reference.color.size(), 0);
    auto inverseDepth = [&](int x, int y) { return 1.0 / reference.depthAt(x, y); };
    auto covered = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && reference.covered(x, y);
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!covered(x, y))
                continue;
            const double here = inverseDepth(x, y);
            for (const auto &[dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
                if (!covered(x - dx, y - dy) || !covered(x + dx, y + dy))
                    continue; // the outline: the coverage band handles it
                const double second =
                    inverseDepth(x + dx, y + dy) + inverseDepth(x - dx, y - dy) - 2.0 * here;
                if (std::abs(second) > relativeJump * here)
                    contour[reference.index(x, y)] = 1;
            }
        }
    }
    return contour;
}

std::vector<std::uint8_t> dilatePixels(const std::vector<std::uint8_t> &mask, int width, int height,
                                       int r)
{
    if (mask.size() != std::size_t(width) * std::size_t(height))
        return {};
    return dilateSquare(mask, width, height, std::max(r, 0));
}

ImageComparison compareImages(const RgbImage &a, const RgbImage &b)
{
    if (a.isNull() || b.isNull() || !a.sameSize(b))
        return {};
    ErrorAccumulator errors;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            errors.add(a.pixel(x, y), b.pixel(x, y), x, y);
    return errors.result();
}

RgbImage errorHeatmap(const RgbImage &rendered, const ReferenceImage &reference, int bandPx,
                      const std::vector<std::uint8_t> *alsoCompared)
{
    if (!sameSize(rendered, reference))
        return {};
    std::vector<std::uint8_t> compared = comparedPixels(reference, bandPx);
    if (alsoCompared && alsoCompared->size() == compared.size())
        for (std::size_t i = 0; i < compared.size(); ++i)
            compared[i] = compared[i] && (*alsoCompared)[i];
    RgbImage heatmap(reference.width, reference.height); // black: uncovered
    for (std::size_t i = 0; i < compared.size(); ++i) {
        if (!reference.coverage[i])
            continue;
        if (!compared[i]) {
            setColor(heatmap.pixel(i), 0, 0, 96);
            continue;
        }
        uchar expected[3];
        encodeReferencePixel(reference, i, expected);
        int worst = 0;
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(int(rendered.pixel(i)[c]) - int(expected[c])));
        setHeatColor(heatmap.pixel(i), worst);
    }
    return heatmap;
}

} // namespace phonglab
