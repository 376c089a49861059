#include "ProgramTrial.h"

#include "ui/viewport/Viewport.h"

#include <algorithm>

namespace phonglab {

double frameBudgetMs(const ViewFrames &frames)
{
    // A program merely slower than the last is no reason to refuse it.
    return std::max(kMinFrameBudgetMs, 4.0 * frames.frameTimes().meanMs());
}

std::shared_ptr<ProgramTrial> ProgramTrial::arm(LentContext &lent, Viewport *viewport,
                                                const std::shared_ptr<GlProgram> &program)
{
    auto trial = std::make_shared<ProgramTrial>();
    trial->budgetMs = frameBudgetMs(viewport->frames());
    trial->pixels = viewport->size() * viewport->devicePixelRatioF();
    // On the worker thread, with the lent context current: the view's
    // renderer only as its borrower may use it.
    const LentRenderer renderer = viewport->glContext().lentRenderer();
    lent.whileCurrent = [renderer, program] { renderer.exchangeProgram(*program); };
    lent.afterWarm = [renderer, program, trial](const LentContext &loan) {
        trial->frameMs = renderer.trialFrameMs(loan, trial->pixels, trial->budgetMs);
        trial->ran = true;
        if (trial->keptOut()) {
            renderer.exchangeProgram(*program); // the new one comes back out
            return;
        }
        *program = GlProgram(); // the previous one, freed in its context
        // Its frame, drawn by the trial, is the view's next: the GUI thread
        // draws nothing more for the new program.
        presentLoanFrame(loan);
    };
    return trial;
}

} // namespace phonglab
