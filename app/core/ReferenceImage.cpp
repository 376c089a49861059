#include "ReferenceImage.h"

#include "PhongReference.h"

#include <algorithm>
#include <limits>

namespace phonglab {

ReferenceImage::ReferenceImage(int w, int h)
    : width(std::max(w, 0))
    , height(std::max(h, 0))
    , color(std::size_t(width) * std::size_t(height), glm::dvec3(0.0))
    , coverage(std::size_t(width) * std::size_t(height), 0)
    , depth(std::size_t(width) * std::size_t(height), std::numeric_limits<double>::infinity())
    , specular(std::size_t(width) * std::size_t(height), glm::dvec3(0.0))
{
}

qint64 ReferenceImage::coveredCount() const
{
    return std::count_if(coverage.begin(), coverage.end(), [](std::uint8_t c) { return c != 0; });
}

QImage ReferenceImage::toImage(const glm::dvec3 &background) const
{
    if (isNull())
        return {};
    QImage image(width, height, QImage::Format_RGB888);
    const uchar bg[3] = {uchar(encodeChannel(background.r)), uchar(encodeChannel(background.g)),
                         uchar(encodeChannel(background.b))};
    for (int y = 0; y < height; ++y) {
        // Write through scanLine: RGB888 rows are padded to 4 bytes, so rows
        // are not contiguous in memory.
        uchar *row = image.scanLine(y);
        for (int x = 0; x < width; ++x) {
            uchar *px = row + 3 * x;
            if (!covered(x, y)) {
                std::copy(bg, bg + 3, px);
                continue;
            }
            const glm::dvec3 &I = colorAt(x, y);
            px[0] = uchar(encodeChannel(I.r));
            px[1] = uchar(encodeChannel(I.g));
            px[2] = uchar(encodeChannel(I.b));
        }
    }
    return image;
}

} // namespace phonglab
