#pragma once
#include "Camera.h"
#include "DepthRange.h"

#include <span>

namespace phonglab {

// Which level of detail an object is drawn with when its "detail" is
// "auto": the coarsest level whose geometric error, projected onto the
// screen, stays within a fraction of a pixel.
//
// A level's error is how far its surface may lie from the full mesh's
// (object units, as the simplifier reports it; level 0, the full mesh, has
// none). Seen from the camera, an error e at distance d covers
//   e / (2·d·tan(fov/2)) · viewport height   pixels;
// d is the distance from the eye to the nearest point of the object's
// bounding sphere (at least the near plane), so the estimate only errs
// towards finer levels.

// Pixels an error of `worldError` spans for an object inside `bounds`.
double projectedErrorPx(double worldError, const BoundingSphere &bounds, const Camera &camera,
                        int viewportHeight);

// Hysteresis, so that a level does not flicker while the camera moves by a
// hair: a level whose error exceeds the target is left at once for a finer
// one (never over the target), but a coarser one is only taken once its
// error is below kCoarsenFraction of the target. Between the two the
// current level stays.
inline constexpr double kCoarsenFraction = 0.7;

// The pixel error the default auto detail allows: half a pixel, and
// calibrated by `phonglab bench --path` to keep shading within the budget.
inline constexpr double kDefaultDetailPixels = 0.5;

// An object no more than this many pixels across shows no shading detail a
// finer level could add: it takes its coarsest level.
inline constexpr double kTinyObjectPx = 4.0;

// `errorsPx`: each level's projected error, level 0 (finest) first, never
// decreasing. `current`: the level drawn last frame, -1 for none (the first
// frame takes the coarsest level within the target). Returns the level to
// draw now.
int chooseDetailLevel(std::span<const double> errorsPx, int current, double targetPx);

} // namespace phonglab
