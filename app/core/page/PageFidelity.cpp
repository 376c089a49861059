#include "PageFidelity.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace phonglab {

namespace {

// 1 where a pixel of the frame sits on an edge (see kEdgeJumpSteps).
std::vector<char> edgeMask(const unsigned char *rgba, int width, int height)
{
    std::vector<char> mask(std::size_t(width) * height, 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < 4 && !mask[std::size_t(y) * width + x]; ++c) {
                int low = 255, high = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = std::clamp(x + dx, 0, width - 1);
                        const int ny = std::clamp(y + dy, 0, height - 1);
                        const int v = rgba[(std::size_t(ny) * width + nx) * 4 + c];
                        low = std::min(low, v);
                        high = std::max(high, v);
                    }
                if (high - low > kEdgeJumpSteps)
                    mask[std::size_t(y) * width + x] = 1;
            }
        }
    return mask;
}

int channelDifference(const unsigned char *a, const unsigned char *b)
{
    int d = 0;
    for (int c = 0; c < 4; ++c)
        d = std::max(d, std::abs(int(a[c]) - int(b[c])));
    return d;
}

// A pixel on a smaller jump (between two facets of face normals): one
// rasteriser gave it the neighbouring triangle, whose colour the other
// image has next to it.
bool onAFacet(const unsigned char *a, const unsigned char *b, QSize size, int x, int y)
{
    const auto at = [&](const unsigned char *image, int px, int py) {
        return image + (std::size_t(py) * size.width() + px) * 4;
    };
    for (const auto &[dx, dy] :
         {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}, std::pair{-1, -1},
          std::pair{1, -1}, std::pair{-1, 1}, std::pair{1, 1}}) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= size.width() || ny >= size.height())
            continue;
        if (channelDifference(at(a, x, y), at(b, nx, ny)) <= kFidelityToleranceSteps
            || channelDifference(at(b, x, y), at(a, nx, ny)) <= kFidelityToleranceSteps)
            return true;
    }
    return false;
}

} // namespace

PageFidelity comparePageFrames(const QByteArray &browser, const QByteArray &here, QSize size)
{
    PageFidelity result;
    result.size = size;
    const qsizetype bytes = qsizetype(size.width()) * size.height() * 4;
    if (size.isEmpty() || browser.size() != bytes || here.size() != bytes) {
        result.largestOutsideEdges = result.largestAnywhere = 255;
        return result;
    }
    const auto *a = reinterpret_cast<const unsigned char *>(browser.constData());
    const auto *b = reinterpret_cast<const unsigned char *>(here.constData());
    const std::vector<char> edgesA = edgeMask(a, size.width(), size.height());
    const std::vector<char> edgesB = edgeMask(b, size.width(), size.height());
    for (int y = 0; y < size.height(); ++y)
        for (int x = 0; x < size.width(); ++x) {
            const std::size_t i = std::size_t(y) * size.width() + x;
            int difference = 0;
            for (int c = 0; c < 4; ++c)
                difference = std::max(difference, std::abs(int(a[i * 4 + c]) - int(b[i * 4 + c])));
            result.largestAnywhere = std::max(result.largestAnywhere, difference);
            if (edgesA[i] || edgesB[i]
                || (difference > kFidelityToleranceSteps && onAFacet(a, b, size, x, y))) {
                ++result.edgePixels;
                continue;
            }
            if (difference > kFidelityToleranceSteps)
                ++result.differingOutsideEdges;
            if (difference > result.largestOutsideEdges) {
                result.largestOutsideEdges = difference;
                result.worst = QPoint(x, size.height() - 1 - y);
            }
        }
    return result;
}

} // namespace phonglab
