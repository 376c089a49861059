#pragma once
#include "core/support/RgbImage.h"

#include <QtGlobal>
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace phonglab {

// What the CPU reference renders: per pixel the unclamped linear intensity I
// of the illumination equation plus whether any surface was hit there. Rows
// run top to bottom (row 0 is the top row), the same as QImage, so a pixel
// (x, y) here is pixel (x, y) of a grabbed framebuffer.
struct ReferenceImage {
    int width = 0;
    int height = 0;
    std::vector<glm::dvec3> color;      // I, not clamped; zero where uncovered
    std::vector<std::uint8_t> coverage; // 1 where a surface was hit
    std::vector<double> depth;          // camera-space distance -z of the hit; +inf where uncovered
    // The specular part of `color` alone (Σ f_att·Is·ks·max(0,R·V)^n, or the
    // Blinn-Phong one), not clamped; zero where uncovered and for the normals
    // view. Lets an error be measured inside the highlight alone.
    std::vector<glm::dvec3> specular;

    ReferenceImage() = default;
    ReferenceImage(int width, int height); // all pixels uncovered

    bool isNull() const { return width <= 0 || height <= 0; }
    std::size_t index(int x, int y) const
    {
        return std::size_t(y) * std::size_t(width) + std::size_t(x);
    }
    bool covered(int x, int y) const { return coverage[index(x, y)] != 0; }
    const glm::dvec3 &colorAt(int x, int y) const { return color[index(x, y)]; }
    double depthAt(int x, int y) const { return depth[index(x, y)]; }
    qint64 coveredCount() const;

    // 8-bit RGB as the GPU would write it: every channel is encodeChannel(I);
    // uncovered pixels get encodeChannel(background).
    RgbImage toImage(const glm::dvec3 &background) const;
};

} // namespace phonglab
