#pragma once
#include <QtGlobal>

namespace phonglab {

// What the view has drawn so far, in one value: what the frame-rate label,
// the trial of a new program and the tests read of it.
struct FrameStats {
    qint64 rendered = 0;  // frames drawn and presented
    qint64 fromLoans = 0; // of those, a new program's first, drawn by its trial (LoanFrame)
    // After a frame longer than kHoldFramesAfterMs the view draws nothing
    // until a click, a wheel turn or a key in it, a new program or a new
    // scene: such a frame is never repeated by itself.
    bool held = false;
    qint64 refused = 0; // frames asked for while held, and not drawn
};

} // namespace phonglab
