#include "DetailSelection.h"

#include <algorithm>
#include <cmath>

namespace phonglab {

double projectedErrorPx(double worldError, const BoundingSphere &bounds, const Camera &camera,
                        int viewportHeight)
{
    const double distance =
        std::max(camera.nearPlane, glm::length(bounds.center - camera.eye) - bounds.radius);
    const double halfHeight = distance * std::tan(glm::radians(camera.fovDeg) / 2.0);
    return worldError / (2.0 * halfHeight) * double(viewportHeight);
}

namespace {

// The coarsest level whose error is at most `limit`; level 0 when none is.
int coarsestWithin(std::span<const double> errorsPx, double limit)
{
    int level = 0;
    for (std::size_t i = 0; i < errorsPx.size(); ++i)
        if (errorsPx[i] <= limit)
            level = int(i);
    return level;
}

} // namespace

int chooseDetailLevel(std::span<const double> errorsPx, int current, double targetPx)
{
    if (errorsPx.empty())
        return 0;
    const int within = coarsestWithin(errorsPx, targetPx);
    if (current < 0 || current >= int(errorsPx.size()))
        return within;
    if (errorsPx[std::size_t(current)] > targetPx)
        return within; // over the target: finer at once
    const int comfortably = coarsestWithin(errorsPx, kCoarsenFraction * targetPx);
    return std::max(current, comfortably);
}

} // namespace phonglab
