#include "LightSetups.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace phonglab {

namespace {

// A light on a ring around the camera target, on the camera's side.
PointLight generatedLight(const Scene &scene, int slot, int slotCount, const PointLight &like)
{
    const Camera &camera = scene.camera;
    const glm::dvec3 toEye = camera.eye - camera.target;
    const double distance = std::max(glm::length(toEye), 1e-6);
    const glm::dvec3 back = toEye / distance;
    glm::dvec3 right = glm::cross(camera.up, back);
    if (glm::length(right) < 1e-9)
        right = glm::dvec3(1, 0, 0);
    right = glm::normalize(right);
    const glm::dvec3 up = glm::cross(back, right);

    // Spread over ±70° around the view direction so every light reaches
    // the visible side; heights alternate so no two lights line up.
    const double t = slotCount > 1 ? double(slot) / double(slotCount - 1) : 0.5;
    const double azimuth = glm::radians(-70.0 + 140.0 * t);
    const double elevation = glm::radians(slot % 2 ? -20.0 : 35.0);
    const double radius = 0.9 * distance;
    const glm::dvec3 direction =
        std::cos(elevation) * (std::cos(azimuth) * back + std::sin(azimuth) * right)
        + std::sin(elevation) * up;

    PointLight light = like;
    light.position = camera.target + radius * direction;
    light.name = "bench light " + std::to_string(slot + 1);
    light.enabled = true;
    return light;
}

} // namespace

std::vector<PointLight> lightsForCount(const Scene &scene, int count)
{
    std::vector<PointLight> own;
    for (const PointLight &l : scene.lights)
        if (l.enabled)
            own.push_back(l);
    count = std::clamp(count, 0, kMaxLights);
    if (count == int(own.size()))
        return own;

    std::vector<PointLight> lights(
        own.begin(), own.begin() + std::min<std::size_t>(own.size(), std::size_t(count)));
    const PointLight fallback; // white, no attenuation
    const int generated = count - int(lights.size());
    for (int i = 0; i < generated; ++i)
        lights.push_back(generatedLight(scene, i, generated,
                                        own.empty() ? fallback : own[std::size_t(i) % own.size()]));
    if (count > int(own.size()) && !own.empty()) {
        const double scale = double(own.size()) / double(count);
        for (PointLight &l : lights) {
            l.diffuse *= scale;
            l.specular *= scale;
        }
    }
    return lights;
}

} // namespace phonglab
