#pragma once
#include "render/gl/SharedGlObject.h"

#include <QSize>

namespace phonglab {

class Renderer;
struct LentContext;

// The view's renderer as a borrower of the view's context may use it
// (ViewContext::lendContext): on the borrowing thread, while the loan lasts,
// when the GUI thread leaves the renderer alone. Only what a new program's
// trial needs (ProgramTrial); handed out by ViewContext::lentRenderer().
class LentRenderer
{
public:
    explicit LentRenderer(Renderer *renderer);

    // Puts `program` in the renderer and hands back, in `program`, the one
    // it drew with; a second call undoes the first.
    void exchangeProgram(GlProgram &program) const;
    // How long one frame of `pixels` takes with the renderer's program, as
    // far as telling it from `limitMs` needs (trialFrameMs).
    double trialFrameMs(const LentContext &loan, const QSize &pixels, double limitMs) const;

private:
    Renderer *m_renderer = nullptr;
};

} // namespace phonglab
