#pragma once
#include "ContextLender.h"
#include "ViewFrames.h"
#include "core/support/FrameLedger.h"
#include "render/gl/LentContext.h"
#include "render/program/WarmUpDraw.h"

#include <QImage>
#include <QObject>
#include <QOpenGLContext>
#include <QSize>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>

class QWidget;
class QWindow;

namespace phonglab {

class FramePresenter;
class ViewportWindow;

// Where the viewport's frames go: its native window (ViewportWindow), the GL
// context made for it, lending that context to other threads, presenting
// (here or on FramePresenter's thread) and timing the frames. What a frame
// shows is the Content's: the surface only knows when to draw, where, and
// how long it took (its FrameLedger books them).
class ViewportSurface : public QObject, public ViewFrames
{
    Q_OBJECT

public:
    // What a frame shows; called with the context current and the window's
    // framebuffer bound.
    class Content
    {
    public:
        virtual ~Content() = default;
        // The scene (false: nothing to time, only the background).
        virtual bool drawScene(const QSize &pixels) = 0;
        // What lies over the scene (the view's child widgets).
        virtual void drawOverlays(const QSize &pixels) = 0;
        // The next frame of `pixels` as a draw another thread may make with
        // the context lent (LoanFrame::draw), or empty where only this
        // thread can draw it (changes not yet sent, overlays to paint).
        virtual std::function<void(const QSize &)> drawForBorrower(const QSize &pixels) = 0;
    };

    // `view`: the widget the window lies in, which gets the window's input
    // and whose size and pixel ratio a frame has. presentOffThread: the
    // wait for the rasteriser and the swap on a thread of their own where
    // the platform allows it (StartupOptions can say no).
    ViewportSurface(QWidget *view, Content *content, bool presentOffThread);
    ~ViewportSurface() override;

    QWindow *window() const override;
    // The widget holding the window, filling the view (a child of it).
    QWidget *container() const { return m_container; }
    // Null before the window was first exposed; invalid when it could not be made.
    QOpenGLContext *context() const { return m_context.get(); }
    bool isStarted() const { return m_context && m_context->isValid(); }
    void makeCurrent();
    void doneCurrent();
    void setFormat(const QSurfaceFormat &format) override;
    QSurfaceFormat format() const;
    // A frame at the next turn of the event loop.
    void requestFrame() override;
    // A frame will be booked (frameTimed) without anyone asking for one:
    // one is asked for, drawn or presented elsewhere, or missed while the
    // context was lent (frames held back are not counted on).
    bool isFrameComing() const override;
    // The next frame is presented off this thread (it follows an edit, and
    // typing goes on meanwhile). Other frames (an orbit's stream) are
    // presented here: handing the context over costs ~3 ms a frame.
    void presentNextOffThread() { m_presentOffThread = true; }

    // See ViewContext::lendContext / takeBackContext.
    std::optional<LentContext> lendContext(QThread *borrower);
    bool takeBackContext(int timeoutMs = -1);
    bool isContextLent() const { return m_lender.isActive(); }

    // Draws and presents a frame, unless the context is lent (then once it
    // is back) or frames are held.
    void drawFrame();
    // A frame drawn now (overlays included) and read back; null before the
    // window was first shown.
    QImage grabFrame();
    // Needs the context current: the bottom-left `pixels` of the window's
    // back buffer, top row first.
    QImage readBackBuffer(const QSize &pixels);
    // The back buffer has the window's size and holds `pixels`: an image
    // that size may be drawn into its corner and read back.
    bool backBufferHolds(const QSize &pixels) const;

    int framebufferSamples() const override { return m_framebufferSamples; }
    std::chrono::steady_clock::time_point lastPresentedAt() const override
    {
        return m_lastPresentedAt;
    }
    const FrameTimeWindow &frameTimes() const override { return m_ledger.times(); }
    FrameStats frameStats() const override { return m_ledger.stats(); }
    void resumeFrames();
    // A new scene or program is drawn once at least, even while frames are held.
    void releaseHold() { m_ledger.releaseHold(); }

    // Frees the surface's own GL objects; the context must be current.
    void destroyGlObjects() { m_warmer.destroy(); }

signals:
    // The context was made (once, at the first exposure) and is current.
    void started();
    void failed(const QString &message);
    // A frame reached the window (after swapBuffers).
    void frameSwapped();
    // A frame's draw time (first GL call to glFinish) was booked.
    void frameTimed(double milliseconds);
    void framesHeldAfter(double milliseconds);

private:
    void start();
    void frameDrawn(double drawMs, bool fromLoan = false);
    void framePresented(quint64 loan, double drawMs, qint64 swappedNs, bool ok);
    std::shared_ptr<LoanFrame> offerLoanFrame();
    void bookPresented(double drawMs, std::chrono::steady_clock::time_point swappedAt,
                       const QSize &backBuffer, bool fromLoan);
    QSize pixels() const; // the view's size in device pixels
    QSize windowPixels() const;

    QWidget *m_view = nullptr;
    Content *m_content = nullptr;
    ViewportWindow *m_window = nullptr; // owned by m_container
    QWidget *m_container = nullptr;     // a child of m_view
    // Made on the first exposure; stays (invalid) when it could not be made.
    std::unique_ptr<QOpenGLContext> m_context;
    ContextLender m_lender;
    // Presents the first frame of a newly adopted program off the GUI
    // thread, so that the keys typed meanwhile are handled at once; null:
    // this thread presents (PHONGLAB_PRESENT_ON_GUI_THREAD=1, or the
    // platform cannot).
    std::unique_ptr<FramePresenter> m_presenter;
    bool m_mayPresentOffThread = true;
    bool m_presentOffThread = false;
    quint64 m_presentLoans = 0; // the newest loan to the presenter: only it ends one
    bool m_frameMissed = false; // asked for while the context was lent
    int m_loanFramesToBook = 0; // presented by a borrower, booked at the next turn
    // The frame the current loan's borrower may present (null: none).
    std::shared_ptr<LoanFrame> m_loanFrame;
    // The window's size (pixels) when a frame was last swapped on this
    // thread: the back buffer's size, which lags a resize until that swap.
    QSize m_presentedSize;
    std::chrono::steady_clock::time_point m_lastPresentedAt;
    WarmUpDraw m_warmer;             // created in this context by a borrower
    GLint m_framebufferSamples = -1; // of the window's framebuffer; -1: not known yet
    FrameLedger m_ledger;
};

} // namespace phonglab
