#pragma once
#include "FrameStats.h"
#include "FrameTimeWindow.h"

namespace phonglab {

// A frame that took longer than this is not drawn again by itself: the view
// waits until the user acts on it.
inline constexpr double kHoldFramesAfterMs = 250.0;

// The view's book of its frames: what each took, how many were drawn, and
// whether it holds its frames after a slow one. No GL and no window: the
// surface tells it what happened and asks it what to do, so the rule that
// a slow frame is never repeated by itself is tested without a context.
class FrameLedger
{
public:
    // A frame was asked for: false while frames are held (it is counted as
    // refused, and resume() asks for it again).
    bool mayDraw();
    // A frame presented at `atNs` (any monotonic clock) that took `drawMs`
    // from its first GL call to glFinish; `fromLoan`: drawn by a borrower
    // of the context (a new program's trial, LoanFrame). True when this
    // frame put the view on hold.
    bool book(qint64 atNs, double drawMs, bool fromLoan = false);
    // The user acted: true when frames were held (the caller then asks for one).
    bool resume();
    // A new scene or program is drawn once at least, even while frames are held.
    void releaseHold() { m_held = false; }
    bool isHeld() const { return m_held; }

    FrameStats stats() const { return {m_rendered, m_fromLoans, m_held, m_refused}; }
    // The draw times of the last second.
    const FrameTimeWindow &times() const { return m_times; }

private:
    FrameTimeWindow m_times;
    qint64 m_rendered = 0;
    qint64 m_fromLoans = 0;
    bool m_held = false;
    qint64 m_refused = 0;
};

} // namespace phonglab
