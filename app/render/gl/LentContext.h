#pragma once
#include <QSemaphore>
#include <QSize>
#include <chrono>
#include <functional>
#include <memory>

class QOpenGLContext;
class QSurface;

namespace phonglab {

class WarmUpDraw;

// The whole frame a borrower may show in the lender's window before it
// gives the context back (the frame after a new program's trial
// is the one the view would draw next, and drawing it there spares the GUI
// thread a second draw and the hand-overs). The lender offers one only when
// nothing it would draw differs: the borrower draws `pixels` with `draw`,
// waits for it and swaps (presentLoanFrame), and says so in the rest.
struct LoanFrame {
    QSize pixels;
    // With the context current and the window's framebuffer bound; touches
    // nothing the lender's thread changes while the context is out.
    std::function<void(const QSize &)> draw;
    QSize windowPixels; // the window's size when lent: its back buffer's after the swap

    // Written by the borrower, read by the lender once the context is back.
    bool drawn = false;     // in the back buffer (drawLoanFrame)
    bool presented = false; // swapped (presentLoanFrame)
    double drawMs = 0.0;    // first GL call to glFinish
    std::chrono::steady_clock::time_point swappedAt;
};

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
    // the new program's frame time, with its shader variant compiled; it
    // may draw and present `frame`).
    std::function<void(const LentContext &)> afterWarm;
    // Null: the borrower presents nothing (a frame the lender must draw
    // itself: something over the scene to paint, a change not yet sent).
    std::shared_ptr<LoanFrame> frame;
};

// With `lent` current on its window: draws lent.frame into the back buffer
// and waits for it (timed in drawMs). False (nothing drawn) without a frame
// or a window.
bool drawLoanFrame(const LentContext &lent);
// Swaps a frame drawLoanFrame drew, and books when. False if none was drawn.
bool presentLoanFrame(const LentContext &lent);

} // namespace phonglab
