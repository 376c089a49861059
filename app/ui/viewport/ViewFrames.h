#pragma once
#include "core/support/FrameStats.h"
#include "core/support/FrameTimeWindow.h"

#include <QSurfaceFormat>
#include <chrono>

class QWindow;

namespace phonglab {

// The view's frames as the window and the tests see them: asking for one,
// whether one is coming, when the last was presented and what they cost.
// Handed out by Viewport::frames(); ViewportSurface, which presents them,
// is what answers.
class ViewFrames
{
public:
    // The format the view's window asks for (samples, depth); set before the
    // window is first shown.
    virtual void setFormat(const QSurfaceFormat &format) = 0;
    // A new frame at the next turn of the event loop (QWidget::update()
    // repaints only the widget around the view's window).
    virtual void requestFrame() = 0;
    // A frame is on its way (frameRendered will come) without asking for one.
    virtual bool isFrameComing() const = 0;
    // The native window the frames go to; its input reaches the view.
    virtual QWindow *window() const = 0;
    // When the last frame was handed to the window system (swapBuffers
    // returned), on whichever thread presented it.
    virtual std::chrono::steady_clock::time_point lastPresentedAt() const = 0;
    // Samples of the framebuffer the view draws into (-1 before the first frame).
    virtual int framebufferSamples() const = 0;
    virtual FrameStats frameStats() const = 0;
    // The draw times behind Viewport::frameRendered()'s figure.
    virtual const FrameTimeWindow &frameTimes() const = 0;

protected:
    ~ViewFrames() = default;
};

} // namespace phonglab
