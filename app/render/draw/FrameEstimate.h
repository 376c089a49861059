#pragma once
#include <QSize>

namespace phonglab {

class Renderer;
struct LentContext;

// The longest whole frame a trial draws on a probe's word alone: a program
// that slow is still kept out, after the view showed its last frame this
// long (the GUI thread does not wait for it).
inline constexpr double kBlindFrameMs = 1000.0;

// How long one frame of `pixelSize` would take with `renderer`'s program, as
// far as telling it from `limitMs` needs: a frame of a 16th
// of its area is drawn into the bound framebuffer and timed to glFinish.
// Over the limit already, or under it even scaled by the area, that settles
// it (its time, a lower bound, or the scaled time, an upper bound, is
// returned). Else a frame of a quarter of the area is drawn too, and
// t = a + b·pixels is fitted through both, so that neither the per-draw cost
// (vertices) nor the per-pixel cost (a fragment shader's loop) is scaled
// wrongly. Needs the renderer's context current.
double estimateFrameMs(Renderer &renderer, const QSize &pixelSize, double limitMs);

} // namespace phonglab

namespace phonglab {

// A new program's trial in the view's lent context: a probe of a
// 256th of the frame's area first, which costs little more than the draw
// itself. Where even that probe scaled by the area promises the frame
// cannot take longer than kBlindFrameMs and the lender offered its next
// frame (lent.frame), that whole frame is drawn into the back buffer, timed
// and kept for presentLoanFrame: the trial costs no draw the view would not
// make anyway. Else estimateFrameMs. Over `limitMs`, nothing is presented.
double trialFrameMs(Renderer &renderer, const LentContext &lent, const QSize &pixelSize,
                    double limitMs);

} // namespace phonglab
