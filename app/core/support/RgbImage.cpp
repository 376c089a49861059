#include "RgbImage.h"

#include <algorithm>

namespace phonglab {

RgbImage::RgbImage(int w, int h)
    : width(std::max(w, 0))
    , height(std::max(h, 0))
    , bytes(3 * std::size_t(width) * std::size_t(height), 0)
{
}

void RgbImage::setPixel(int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b)
{
    std::uint8_t *p = pixel(x, y);
    p[0] = r;
    p[1] = g;
    p[2] = b;
}

void RgbImage::fill(std::uint8_t r, std::uint8_t g, std::uint8_t b)
{
    for (std::size_t i = 0; i < pixelCount(); ++i) {
        std::uint8_t *p = pixel(i);
        p[0] = r;
        p[1] = g;
        p[2] = b;
    }
}

} // namespace phonglab
