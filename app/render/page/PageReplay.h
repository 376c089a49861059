#pragma once
#include "core/page/PageCapture.h"
#include "core/support/Result.h"

#include <QByteArray>
#include <QStringList>

namespace phonglab {

// The captured frame drawn again here: each program built as PhongLab
// builds a student's (render/program/ProgramBuilder: the browser's rules on this
// driver), each clear and draw with the state, uniforms and buffers the
// browser had. Its pixels against the browser's say whether PhongLab runs
// the page's code as the browser did (the fidelity check, core/page/PageFidelity):
// a difference there is PhongLab's, never the student's.
struct ReplayedFrame {
    QByteArray pixels; // RGBA, bottom row first, the canvas's size
    // What could not be drawn as the browser drew it (a texture, a draw
    // past its buffers), each in a sentence: the comparison then says so.
    QStringList notReplayed;
};

// On the current context (a desktop GL 3.3 core one, as OffscreenRenderer
// makes). A failure when nothing can be drawn (no canvas, a program that
// does not build here).
Result<ReplayedFrame> replayCapture(const PageCapture &capture);

} // namespace phonglab
