#include "LentContext.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>

namespace phonglab {

bool drawLoanFrame(const LentContext &lent)
{
    LoanFrame *frame = lent.frame.get();
    if (!frame || !frame->draw || !lent.surface || frame->pixels.isEmpty())
        return false;
    QOpenGLFunctions *gl = lent.context->functions();
    const auto started = std::chrono::steady_clock::now();
    gl->glBindFramebuffer(GL_FRAMEBUFFER, lent.context->defaultFramebufferObject());
    frame->draw(frame->pixels);
    gl->glFinish(); // without it the time would be the submission's
    frame->drawMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    frame->drawn = true;
    return true;
}

bool presentLoanFrame(const LentContext &lent)
{
    LoanFrame *frame = lent.frame.get();
    if (!frame || !frame->drawn)
        return false;
    lent.context->swapBuffers(lent.surface);
    frame->swappedAt = std::chrono::steady_clock::now();
    frame->presented = true;
    return true;
}

} // namespace phonglab
