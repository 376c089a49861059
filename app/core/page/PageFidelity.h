#pragma once
#include <QByteArray>
#include <QPoint>
#include <QSize>

namespace phonglab {

// The browser's frame against the same frame drawn again by PhongLab
// (render/page/PageReplay). Both rasterise the same triangles, but where a
// pixel's centre lies on an edge the two rasterisers may each give it to
// another triangle; those pixels are told apart by the jump across them
// and left out: a pixel is on an edge where, in either frame, the values
// in its 3x3 neighbourhood span more than kEdgeJumpSteps in a channel.
// Smooth shading changes by a few steps per pixel, so an edge pixel's
// error is bounded by the jump it sits on, and everything else is compared.
// A pixel on a smaller jump (between facets of face normals) is an edge
// pixel too where it has, in one frame, the colour its neighbour has in the
// other: the same flip of a pixel centre from one triangle to the next.
inline constexpr int kEdgeJumpSteps = 8;
// Largest difference, in 8-bit steps, that still means "drawn as the
// browser drew it": each rasteriser rounds its floats its own way.
inline constexpr int kFidelityToleranceSteps = 2;

struct PageFidelity {
    QSize size;
    int largestOutsideEdges = 0; // 8-bit steps, any channel of RGBA
    int largestAnywhere = 0;
    qint64 edgePixels = 0;
    qint64 differingOutsideEdges = 0; // by more than the tolerance
    QPoint worst{-1, -1};             // outside edges, row 0 at the top; (-1, -1) when none differs

    bool faithful() const { return largestOutsideEdges <= kFidelityToleranceSteps; }
};

// Both RGBA, bottom row first (as readPixels), of `size`.
PageFidelity comparePageFrames(const QByteArray &browser, const QByteArray &here, QSize size);

} // namespace phonglab
