#pragma once
#include <QSize>

namespace phonglab {

class Renderer;

// How long one frame of `pixelSize` would take with `renderer`'s program, as
// far as telling it from `limitMs` needs (issue 31, C): a frame of a 16th
// of its area is drawn into the bound framebuffer and timed to glFinish.
// Over the limit already, or under it even scaled by the area, that settles
// it (its time, a lower bound, or the scaled time, an upper bound, is
// returned). Else a frame of a quarter of the area is drawn too, and
// t = a + b·pixels is fitted through both, so that neither the per-draw cost
// (vertices) nor the per-pixel cost (a fragment shader's loop) is scaled
// wrongly. Needs the renderer's context current.
double estimateFrameMs(Renderer &renderer, const QSize &pixelSize, double limitMs);

} // namespace phonglab
