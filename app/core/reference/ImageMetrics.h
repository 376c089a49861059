#pragma once
#include "ReferenceImage.h"
#include "core/support/RgbImage.h"

#include <QPoint>
#include <QString>

namespace phonglab {

// How far an 8-bit render is from another image or from the CPU reference,
// in 8-bit steps per channel.
struct ImageComparison {
    double psnr = 0;   // 20·log10(255 / rmse) dB; +inf when identical; 0 when nothing was compared
    double rmse = 0;   // over every compared channel value
    int maxError = 0;  // largest |difference| of one channel, 0..255
    QPoint worstPixel; // first pixel (row-major) with maxError
    qint64 pixelsCompared = 0; // 0 on a size mismatch

    // "PSNR 54.21 dB, RMSE 0.49, max 2/255 at (120,88), 41234 px"
    QString summary() const;
};

// Compares `rendered` with the reference quantised by encodeChannel(), over
// the pixels the reference covers that lie more than bandPx pixels
// (Chebyshev distance) from every silhouette pixel. A silhouette pixel is one
// whose coverage differs from one of its 8 neighbours; both sides of an edge
// count, so bandPx = 0 already leaves out the edge pixels themselves, which a
// tessellated mesh covers differently from the analytic surface.
ImageComparison compareWithReference(const RgbImage &rendered, const ReferenceImage &reference,
                                     int bandPx);

// What the speed-against-accuracy bench measures: every pixel more than
// bandPx from a silhouette of the reference where either image shows a
// surface — the reference's covered pixels, and the ones the render covers
// although the reference shows `background` there (a coarse mesh bulging out
// of the true outline). With a mask, only pixels where mask[i] != 0.
struct BandComparison {
    ImageComparison error;
    qint64 coverageErrors = 0; // compared pixels covered in one image and not in the other
};
BandComparison compareOutsideBand(const RgbImage &rendered, const ReferenceImage &reference,
                                  const glm::dvec3 &background, int bandPx,
                                  const std::vector<std::uint8_t> *mask = nullptr);

// Pixels next to an occluding contour inside the reference: where one
// surface passes in front of another, so the covered pixels on either side
// belong to different surfaces (the tree's tiers). Checked per axis on the
// second difference of inverse depth over neighbouring pixels, which is zero
// on any plane whatever its angle and small on smooth surfaces, and jumps
// across an occlusion: flagged where it exceeds `relativeJump` · 1/z.
// Together with the outline these are the silhouettes the bench's band
// leaves out.
std::vector<std::uint8_t> occludingContourPixels(const ReferenceImage &reference,
                                                 double relativeJump = 0.002);

// Every pixel within Chebyshev distance r of a set pixel of `mask`.
std::vector<std::uint8_t> dilatePixels(const std::vector<std::uint8_t> &mask, int width, int height,
                                       int r);

// Every pixel, R, G and B.
ImageComparison compareImages(const RgbImage &a, const RgbImage &b);

// A picture of where compareWithReference() found errors, for saving next to a
// failing test: compared pixels ramp from dark green (exact) through yellow to
// red (8/255 or more off), band pixels are dark blue, uncovered ones black.
// Null on a size mismatch. With `alsoCompared`, pixels where it is 0 count
// as band too (the bench's occluding contours).
RgbImage errorHeatmap(const RgbImage &rendered, const ReferenceImage &reference, int bandPx,
                      const std::vector<std::uint8_t> *alsoCompared = nullptr);

} // namespace phonglab
