#pragma once
#include "render/gl/LentContext.h"
#include "render/gl/SharedGlObject.h"

#include <QSize>
#include <memory>

namespace phonglab {

class Viewport;
class ViewFrames;

// A new program whose frame would take longer than a few frames of the view,
// and at least this, is kept out (docs/first-five-minutes.md).
inline constexpr double kMinFrameBudgetMs = 250.0;

// The budget for the view as it draws now: 4 frames of it, at least
// kMinFrameBudgetMs.
double frameBudgetMs(const ViewFrames &frames);

// One new program tried in the viewport's lent context before the view
// takes it: armed on a loan, it puts the program in the renderer while the
// context is current, tries one frame after the warm-up draw
// (trialFrameMs) and, over the budget, takes it out again; within it, the
// frame the trial drew is presented from there (LoanFrame). `program`
// holds whichever program is not in the renderer: the one kept out, or
// nothing once the previous one was freed.
struct ProgramTrial {
    double budgetMs = 0.0;
    QSize pixels;
    double frameMs = 0.0;
    bool ran = false;

    bool keptOut() const { return ran && frameMs > budgetMs; }
    static std::shared_ptr<ProgramTrial> arm(LentContext &lent, Viewport *viewport,
                                             const std::shared_ptr<GlProgram> &program);
};

} // namespace phonglab
