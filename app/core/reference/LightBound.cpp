#include "LightBound.h"

#include "PhongReference.h"

#include <algorithm>
#include <cmath>

namespace phonglab {

double maxLightContribution(const PointLight &light, const Material &material,
                            const BoundingSphere &bounds)
{
    if (!light.enabled)
        return 0.0;
    const double nearest =
        std::max(0.0, glm::length(light.position - bounds.center) - bounds.radius);
    const glm::dvec3 peak = light.diffuse * material.kd + light.specular * material.ks;
    return attenuationFactor(light.attenuation, nearest) * std::max({peak.r, peak.g, peak.b});
}

namespace {

// max over φ of n·cos^(n-1)φ·sin φ: the steepest slope of cos^n.
double steepestSpecularSlope(double n)
{
    if (n <= 1.0)
        return 1.0;
    const double phi = std::atan(1.0 / std::sqrt(n - 1.0));
    return n * std::pow(std::cos(phi), n - 1.0) * std::sin(phi);
}

} // namespace

double normalErrorBound(double angle, const Material &material, std::span<const PointLight> lights,
                        const BoundingSphere &bounds)
{
    const double slope = steepestSpecularSlope(material.shininess);
    glm::dvec3 sum(0.0);
    for (const PointLight &light : lights) {
        if (!light.enabled)
            continue;
        const double nearest =
            std::max(0.0, glm::length(light.position - bounds.center) - bounds.radius);
        sum += attenuationFactor(light.attenuation, nearest)
            * (light.diffuse * material.kd * angle
               + light.specular * material.ks * 2.0 * angle * slope);
    }
    return std::max({sum.r, sum.g, sum.b});
}

std::vector<int> enabledLights(std::span<const PointLight> lights)
{
    std::vector<int> enabled;
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (lights[i].enabled)
            enabled.push_back(int(i));
    return enabled;
}

LightSelection selectLights(std::span<const PointLight> lights, const Material &material,
                            const BoundingSphere &bounds, double allowance)
{
    std::vector<int> order;
    std::vector<double> bound(lights.size(), 0.0);
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (lights[i].enabled) {
            order.push_back(int(i));
            bound[i] = maxLightContribution(lights[i], material, bounds);
        }
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return bound[std::size_t(a)] < bound[std::size_t(b)]; });

    LightSelection selection;
    std::vector<bool> dropped(lights.size(), false);
    for (int i : order) {
        const double sum = selection.leftOutBound + bound[std::size_t(i)];
        if (!(sum < allowance))
            break;
        selection.leftOutBound = sum;
        dropped[std::size_t(i)] = true;
    }
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (!lights[i].enabled)
            continue;
        (dropped[i] ? selection.leftOut : selection.kept).push_back(int(i));
    }
    return selection;
}

} // namespace phonglab
