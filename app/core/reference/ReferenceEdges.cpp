#include "core/reference/ReferenceEdges.h"

#include "ImageMetrics.h"
#include "core/reference/MeshRaycaster.h"
#include "core/support/ParallelRows.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ReferenceEdgesWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ReferenceEdges)
};

namespace {

// Relative size of a jump in inverse depth (about the same relative jump in
// depth) that counts as an occluding edge; see the header.
constexpr double kJumpTolerance = 1e-3;

// Whether a, c, b (inverse depths at -step, 0, +step along one axis) lie on
// one continuous surface.
bool continuous(double a, double c, double b)
{
    return std::abs(a + b - 2.0 * c) <= kJumpTolerance * c;
}

void classifyRow(const SceneDepthCaster &caster, double step, std::uint8_t *row, int y)
{
    const double py = y + 0.5;
    for (int x = 0; x < caster.width(); ++x) {
        const double px = x + 0.5;
        const double centre = caster.depthAt(px, py);
        const double shifted[4] = {caster.depthAt(px - step, py), caster.depthAt(px + step, py),
                                   caster.depthAt(px, py - step), caster.depthAt(px, py + step)};
        const bool covered = std::isfinite(centre);
        bool ambiguous = false;
        for (const double depth : shifted)
            ambiguous = ambiguous || std::isfinite(depth) != covered;
        if (covered && !ambiguous)
            ambiguous = !continuous(1.0 / shifted[0], 1.0 / centre, 1.0 / shifted[1])
                || !continuous(1.0 / shifted[2], 1.0 / centre, 1.0 / shifted[3]);
        row[x] = ambiguous ? 1 : 0;
    }
}

} // namespace

Result<std::vector<std::uint8_t>> ambiguousReferencePixels(
    const Scene &scene, const std::vector<std::shared_ptr<const MeshData>> &objectMeshes, int width,
    int height, int subpixelBits)
{
    const Result<std::unique_ptr<SceneDepthCaster>> created =
        SceneDepthCaster::create(scene, objectMeshes, width, height);
    if (!created)
        return fail(created.error());
    const SceneDepthCaster *caster = created->get();
    // OpenGL requires at least 4 sub-pixel bits; more than 30 would only
    // test the rounding of double.
    const double step = std::ldexp(1.0, -std::clamp(subpixelBits, 4, 30));
    std::vector<std::uint8_t> mask(std::size_t(width) * std::size_t(height), 0);

    forEachRowInParallel(height, [&](int y) {
        classifyRow(*caster, step, mask.data() + std::size_t(y) * std::size_t(width), y);
    });
    return mask;
}

Result<std::vector<std::uint8_t>> awayFromSilhouettes(
    const ReferenceImage &reference, const Scene &scene,
    const std::vector<std::shared_ptr<const MeshData>> &objectMeshes, int bandPx)
{
    std::vector<std::uint8_t> edges = occludingContourPixels(reference);
    const Result<std::vector<std::uint8_t>> ambiguous = ambiguousReferencePixels(
        scene, objectMeshes, reference.width, reference.height, kDefaultSubpixelBits);
    if (!ambiguous)
        return fail(ambiguous.error());
    if (ambiguous->size() != edges.size())
        return fail(ReferenceEdgesWords::tr(
                        "The reference is %1x%2 but the edges were cast at another size")
                        .arg(reference.width)
                        .arg(reference.height));
    for (std::size_t i = 0; i < edges.size(); ++i)
        edges[i] = edges[i] || (*ambiguous)[i];
    std::vector<std::uint8_t> compared =
        dilatePixels(edges, reference.width, reference.height, bandPx);
    for (auto &c : compared)
        c = !c;
    return compared;
}

} // namespace phonglab
