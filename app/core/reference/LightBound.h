#pragma once
#include "core/scene/Material.h"
#include "core/scene/PointLight.h"
#include "core/view/DepthRange.h"

#include <span>
#include <vector>

namespace phonglab {

// How much one light can add to any pixel of an object, at most, and which
// lights an object's draw can therefore leave out.
//
// A light adds f_att·(Id·kd·max(0, N·L) + Is·ks·max(0, R·V)^n) to a channel.
// Both dot products are at most 1, and f_att falls with distance (the scene
// loader keeps c1, c2, c3 ≥ 0), so over an object inside `bounds` the term is
// at most f_att(d_min)·(Id·kd + Is·ks), d_min being the distance from the
// light to the nearest point of the bounds (0 inside them). The bound is
// that, in the largest channel. A disabled light adds nothing.
double maxLightContribution(const PointLight &light, const Material &material,
                            const BoundingSphere &bounds);

// How much a normal that is off by `angle` radians can change the shading
// of any pixel of an object inside `bounds` (linear intensity, largest
// channel), summed over the enabled lights: N·L moves by at most the angle,
// R by twice it, and cos^n of the angle between R and V by at most
// S(n) = max over φ of n·cos^(n-1)φ·sin φ per radian, so
//   Σ f_att(d_min)·(Id·kd·angle + Is·ks·2·angle·S(n)).
// Exact to first order; where N·L changes sign the highlight's cut-off can
// jump further, which the measurement (bench --path) would show.
double normalErrorBound(double angle, const Material &material, std::span<const PointLight> lights,
                        const BoundingSphere &bounds);

// The indices of the enabled lights, in order.
std::vector<int> enabledLights(std::span<const PointLight> lights);

struct LightSelection {
    std::vector<int> kept;     // indices into the lights given, in their order
    std::vector<int> leftOut;  // enabled lights the draw does without
    double leftOutBound = 0.0; // sum of their bounds: the most any pixel can change
};

// Leaves out the enabled lights of smallest bound for as long as the sum of
// the bounds left out stays strictly below `allowance` (linear intensity;
// allowance·255 is in 8-bit steps: a sum below k steps changes no encoded
// channel by more than k). So no light that could change a pixel by the
// allowance or more is ever left out, alone or together with others.
// allowance ≤ 0 keeps every enabled light. Disabled lights are in neither list.
LightSelection selectLights(std::span<const PointLight> lights, const Material &material,
                            const BoundingSphere &bounds, double allowance);

} // namespace phonglab
