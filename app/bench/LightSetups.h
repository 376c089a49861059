#pragma once
#include "core/scene/Scene.h"

#include <vector>

namespace phonglab {

// The lights a bench configuration with `count` lights uses: the scene's own
// enabled lights first, then generated ones on a ring in front of the scene
// (facing the camera, alternating above and below the view height), coloured
// like the scene's lights in turn.
//
// Why scaled: with more lights than the scene has, every light's Id and Is
// are scaled by (scene lights / count) so the picture keeps about the same
// brightness. Without that, eight unscaled lights clip most of the image to
// white, where every method is "exact" and the comparison says nothing.
//
// When `count` equals the scene's own enabled light count the result is
// exactly the scene's lights (no scaling).
std::vector<PointLight> lightsForCount(const Scene &scene, int count);

} // namespace phonglab
