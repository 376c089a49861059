#include "ProgramTrial.h"

#include "render/FrameEstimate.h"
#include "ui/viewport/Viewport.h"

#include <algorithm>

namespace phonglab {

double frameBudgetMs(const Viewport &viewport)
{
    // A program merely slower than the last is no reason to refuse it.
    return std::max(kMinFrameBudgetMs, 4.0 * viewport.frameTimes().meanMs());
}

std::shared_ptr<ProgramTrial> ProgramTrial::arm(LentContext &lent, Viewport *viewport,
                                                const std::shared_ptr<GlProgram> &program)
{
    auto trial = std::make_shared<ProgramTrial>();
    trial->budgetMs = frameBudgetMs(*viewport);
    trial->pixels = viewport->size() * viewport->devicePixelRatioF();
    lent.whileCurrent = [viewport, program] { viewport->renderer().exchangeProgram(*program); };
    lent.afterWarm = [viewport, program, trial](const LentContext &loan) {
        Renderer &renderer = viewport->renderer();
        trial->frameMs = trialFrameMs(renderer, loan, trial->pixels, trial->budgetMs);
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
