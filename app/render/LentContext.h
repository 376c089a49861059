#pragma once
#include <QSemaphore>
#include <functional>
#include <memory>

class QOpenGLContext;
class QSurface;

namespace phonglab {

class WarmUpDraw;

// A view's context lent to another thread, the way Qt documents drawing off
// the GUI thread with one context: the owner stops painting, releases
// the context and moves it to the borrower's thread. The borrower makes it
// current on a surface of its own, draws, releases it, moves it back to the
// owner's thread and only then releases `returned`; the owner waits on that
// before it touches GL again.
struct LentContext {
    QOpenGLContext *context = nullptr;
    // The lender's window: the borrower draws into its framebuffer, which
    // nobody else touches while the context is out (null: no window; the
    // borrower's own surface then, and a framebuffer object).
    QSurface *surface = nullptr;
    WarmUpDraw *warmer = nullptr; // owned by the lender, lives in `context`
    int samples = 0;              // of the lender's framebuffer
    std::shared_ptr<QSemaphore> returned;
    // Runs on the borrower's thread with the context current, before the
    // warm-up draw (e.g. switching the renderer to the new program, whose
    // first use in a context has a cost of its own on llvmpipe).
    std::function<void()> whileCurrent;
    // Runs after the warm-up draw, the context still current (a trial of
    // the new program's frame time, with its shader variant compiled).
    std::function<void()> afterWarm;
};

} // namespace phonglab
