#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace phonglab {

// An 8-bit RGB picture as the GPU writes a framebuffer: rows top to bottom,
// three bytes a pixel, packed (no row padding). What the reference, the
// image comparison and the shader check work on, so core needs no Qt GUI;
// render/gl/QtImages.h converts to and from QImage.
struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> bytes; // width · height · 3

    RgbImage() = default;
    RgbImage(int width, int height); // black

    bool isNull() const { return width <= 0 || height <= 0; }
    bool sameSize(const RgbImage &other) const
    {
        return width == other.width && height == other.height;
    }
    std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
    // Pixel i (row-major) or (x, y): its R, G, B.
    const std::uint8_t *pixel(std::size_t i) const { return bytes.data() + 3 * i; }
    std::uint8_t *pixel(std::size_t i) { return bytes.data() + 3 * i; }
    const std::uint8_t *pixel(int x, int y) const
    {
        return pixel(std::size_t(y) * std::size_t(width) + std::size_t(x));
    }
    std::uint8_t *pixel(int x, int y)
    {
        return pixel(std::size_t(y) * std::size_t(width) + std::size_t(x));
    }
    void setPixel(int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b);
    void fill(std::uint8_t r, std::uint8_t g, std::uint8_t b);

    bool operator==(const RgbImage &) const = default;
};

} // namespace phonglab
