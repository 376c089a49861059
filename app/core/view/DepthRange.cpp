#include "DepthRange.h"
#include "core/support/Language.h"

#include <QCoreApplication>
#include <QString>

#include <algorithm>
#include <cmath>
#include <limits>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct DepthRangeWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::DepthRange)
};

BoundingSphere boundingSphere(const glm::dvec3 &lo, const glm::dvec3 &hi, const glm::dmat4 &model)
{
    // The box's eight corners after the model matrix, then the sphere around
    // their box: exact containment under any affine model (shear, mirror).
    glm::dvec3 mn(std::numeric_limits<double>::infinity()),
        mx(-std::numeric_limits<double>::infinity());
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
        const glm::dvec3 p = glm::dvec3(model * glm::dvec4(corner, 1.0));
        mn = glm::min(mn, p);
        mx = glm::max(mx, p);
    }
    return {0.5 * (mn + mx), 0.5 * glm::length(mx - mn)};
}

DepthRange fitDepthRange(const Camera &camera, std::span<const BoundingSphere> spheres)
{
    const DepthRange asked{camera.nearPlane, camera.farPlane};
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    double nearest = std::numeric_limits<double>::infinity();
    double farthest = -std::numeric_limits<double>::infinity();
    for (const BoundingSphere &s : spheres) {
        const double depth = glm::dot(s.center - camera.eye, forward);
        if (!std::isfinite(depth) || !std::isfinite(s.radius))
            return asked; // cannot bound it: draw what the camera asked for
        nearest = std::min(nearest, depth - s.radius);
        farthest = std::max(farthest, depth + s.radius);
    }
    // Slack: the spheres are in double, the GPU's vertices in float.
    DepthRange fitted{std::max(asked.nearPlane, nearest * (1.0 - 1e-3)),
                      std::min(asked.farPlane, farthest * (1.0 + 1e-3))};
    if (!(fitted.nearPlane < fitted.farPlane))
        return asked; // nothing between the planes: nothing to gain
    return fitted;
}

std::optional<QString> depthPrecisionWarning(const DepthRange &range)
{
    if (!(range.ratio() > kDepthRatioWarning))
        return std::nullopt;
    const double resolved =
        100.0 * range.ratio() / double(1 << 24); // percent of the distance, at far
    const QString effect = resolved < 50.0
        ? DepthRangeWords::tr(
              "surfaces closer than about %1 % of their distance may show through each other")
              .arg(sentenceNumber(resolved, 'g', 2))
        : DepthRangeWords::tr("the depth buffer cannot tell surfaces apart");
    return DepthRangeWords::tr(
               "camera: near %1 and far %2 are %3 orders of magnitude apart (the eye is inside an "
               "object's bounds); %4: raise near")
        .arg(sentenceNumber(range.nearPlane, 'g', 3))
        .arg(sentenceNumber(range.farPlane, 'g', 3))
        .arg(std::log10(range.ratio()), 0, 'f', 0)
        .arg(effect);
}

} // namespace phonglab
