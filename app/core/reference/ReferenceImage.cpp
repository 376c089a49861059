#include "core/reference/ReferenceImage.h"

#include "core/reference/PhongReference.h"

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

RgbImage ReferenceImage::toImage(const glm::dvec3 &background) const
{
    if (isNull())
        return {};
    RgbImage image(width, height);
    const std::uint8_t bg[3] = {std::uint8_t(encodeChannel(background.r)),
                                std::uint8_t(encodeChannel(background.g)),
                                std::uint8_t(encodeChannel(background.b))};
    for (std::size_t i = 0; i < color.size(); ++i) {
        std::uint8_t *px = image.pixel(i);
        if (!coverage[i]) {
            std::copy(bg, bg + 3, px);
            continue;
        }
        for (int c = 0; c < 3; ++c)
            px[c] = std::uint8_t(encodeChannel(color[i][c]));
    }
    return image;
}

} // namespace phonglab
