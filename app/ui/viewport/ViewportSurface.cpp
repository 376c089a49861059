#include "ViewportSurface.h"

#include "FramePresenter.h"
#include "ViewportWindow.h"

#include <QOpenGLExtraFunctions>
#include <QOpenGLFunctions>
#include <QWidget>
#include <algorithm>
#include <utility>

namespace phonglab {

namespace {

double msSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

} // namespace

ViewportSurface::ViewportSurface(QWidget *view, Content *content, bool presentOffThread)
    : QObject(view)
    , m_view(view)
    , m_content(content)
    , m_window(new ViewportWindow(this, view))
    , m_mayPresentOffThread(presentOffThread)
{
    m_container = QWidget::createWindowContainer(m_window, view);
    // Events made for the view (tests, drops found by position) reach it,
    // not the container; the window's own input is passed on by ViewportWindow.
    m_container->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_container->setFocusPolicy(Qt::NoFocus);
}

ViewportSurface::~ViewportSurface()
{
    if (m_lender.isActive()) {
        // A borrower stuck in the driver: its context is left, as said, and
        // a stuck presenter's thread too (waiting for it would never end).
        if (m_presenter && m_lender.borrower() == m_presenter->presenterThread())
            (void)m_presenter.release();
        (void)m_context.release();
    }
}

QWindow *ViewportSurface::window() const
{
    return m_window;
}

void ViewportSurface::makeCurrent()
{
    if (isStarted())
        m_context->makeCurrent(m_window);
}

void ViewportSurface::doneCurrent()
{
    if (m_context && QOpenGLContext::currentContext() == m_context.get())
        m_context->doneCurrent();
}

void ViewportSurface::setFormat(const QSurfaceFormat &format)
{
    m_window->setFormat(format);
}

QSurfaceFormat ViewportSurface::format() const
{
    return isStarted() ? m_context->format() : m_window->requestedFormat();
}

void ViewportSurface::requestFrame()
{
    m_window->requestFrame();
}

bool ViewportSurface::isFrameComing() const
{
    const bool presenting = m_presenter && m_lender.borrower() == m_presenter->presenterThread();
    return m_window->isFramePending() || m_frameMissed || m_loanFramesToBook > 0 || presenting;
}

QSize ViewportSurface::pixels() const
{
    return m_view->size() * m_view->devicePixelRatioF();
}

QSize ViewportSurface::windowPixels() const
{
    return m_window->size() * m_window->devicePixelRatio();
}

bool ViewportSurface::backBufferHolds(const QSize &pixels) const
{
    const QSize window = windowPixels();
    // A window resized since its last frame may still have a back buffer
    // of the old size (Mesa takes the new one at the next swap).
    return m_window->isExposed() && m_presentedSize == window && pixels.width() <= window.width()
        && pixels.height() <= window.height();
}

std::optional<LentContext> ViewportSurface::lendContext(QThread *borrower)
{
    // A frame being presented is waited for first (a frame's time).
    if (!isStarted() || !takeBackContext())
        return std::nullopt;
    // A loan is for a new program's warm-up (the borrower may switch the
    // renderer to it, and present its first frame): the frames after it
    // follow an edit (the check's pictures coming over the view).
    m_presentOffThread = true;
    // The warm-up draws into the window's own framebuffer only where a
    // context may be current on a window off the GUI thread.
    QSurface *surface = QOpenGLContext::supportsThreadedOpenGL() ? m_window : nullptr;
    std::optional<LentContext> lent = m_lender.lend(m_context.get(), surface, borrower, &m_warmer,
                                                    std::max(0, m_framebufferSamples));
    if (lent && surface) {
        m_loanFrame = offerLoanFrame();
        lent->frame = m_loanFrame;
    }
    return lent;
}

// The frame a borrower may present in this window: only where it is the
// frame this thread would draw next, overlays and all, into a back buffer
// of the window's size, and where frames are presented off this thread at
// all (the platform allows it).
std::shared_ptr<LoanFrame> ViewportSurface::offerLoanFrame()
{
    const QSize frame = pixels();
    if (!m_presenter || m_ledger.isHeld() || !backBufferHolds(frame))
        return nullptr;
    std::function<void(const QSize &)> draw = m_content->drawForBorrower(frame);
    if (!draw)
        return nullptr;
    auto offered = std::make_shared<LoanFrame>();
    offered->pixels = frame;
    offered->draw = std::move(draw);
    offered->windowPixels = windowPixels();
    return offered;
}

bool ViewportSurface::takeBackContext(int timeoutMs)
{
    QThread *borrower = m_lender.borrower();
    if (!m_lender.end(timeoutMs))
        return false;
    // Back from a warm-up, whose borrower may have switched the renderer to
    // the new program: its frame is due, as is any asked for meanwhile,
    // unless the borrower presented that frame itself (LoanFrame).
    const bool fromWarmUp =
        borrower && (!m_presenter || borrower != m_presenter->presenterThread());
    const std::shared_ptr<LoanFrame> loanFrame = std::exchange(m_loanFrame, nullptr);
    const bool presentedOnLoan = fromWarmUp && loanFrame && loanFrame->presented;
    if (presentedOnLoan) {
        ++m_loanFramesToBook;
        // Booked at the next turn of the event loop, as a presenter's frame
        // is: whoever took the context back finishes first (the controller
        // says the program is applied, then the frame is seen).
        QMetaObject::invokeMethod(
            this,
            [this, loanFrame] {
                --m_loanFramesToBook;
                bookPresented(loanFrame->drawMs, loanFrame->swappedAt, loanFrame->windowPixels,
                              /*fromLoan=*/true);
            },
            Qt::QueuedConnection);
    }
    if (m_frameMissed || (fromWarmUp && !presentedOnLoan)) {
        m_frameMissed = false;
        requestFrame();
    }
    return true;
}

// Once, on the first exposure: the context for the window's format, sharing
// objects with the rest of the application (the build thread's context).
void ViewportSurface::start()
{
    m_context = std::make_unique<QOpenGLContext>();
    m_context->setFormat(m_window->requestedFormat());
    m_context->setShareContext(QOpenGLContext::globalShareContext());
    if (!m_context->create() || !m_context->makeCurrent(m_window)) {
        emit failed(tr("Cannot create an OpenGL context for the viewport"));
        m_context = std::make_unique<QOpenGLContext>(); // invalid: no second try
        return;
    }
    if (m_mayPresentOffThread && QOpenGLContext::supportsThreadedOpenGL()) {
        m_presenter = std::make_unique<FramePresenter>();
        connect(m_presenter.get(), &FramePresenter::presented, this,
                &ViewportSurface::framePresented, Qt::QueuedConnection);
    }
    emit started();
}

void ViewportSurface::drawFrame()
{
    if (!m_ledger.mayDraw())
        return; // resumeFrames() asks for the frame
    if (m_lender.isActive()) {
        m_frameMissed = true;
        return;
    }
    if (!m_window->isExposed())
        return;
    if (!m_context)
        start();
    if (!isStarted() || !m_context->makeCurrent(m_window))
        return;
    QOpenGLFunctions *f = m_context->functions();
    const auto started = std::chrono::steady_clock::now();
    f->glBindFramebuffer(GL_FRAMEBUFFER, m_context->defaultFramebufferObject());
    if (m_framebufferSamples < 0) {
        // What the window really got, not what was asked for: a warm-up
        // must draw with the same.
        f->glGetIntegerv(GL_SAMPLES, &m_framebufferSamples);
    }
    const bool scene = m_content->drawScene(pixels());
    m_content->drawOverlays(pixels());
    if (scene && m_presenter && std::exchange(m_presentOffThread, false)) {
        // The wait for the rasteriser and the swap go to the presenter's
        // thread; this one goes back to its events (typing) meanwhile.
        std::optional<LentContext> lent =
            m_lender.lend(m_context.get(), m_window, m_presenter->presenterThread(), nullptr,
                          std::max(0, m_framebufferSamples));
        m_presenter->present(++m_presentLoans, std::move(*lent), thread(), started);
        return;
    }
    if (scene) {
        f->glFinish(); // without it the time would be the submission's
        frameDrawn(msSince(started));
    }
    m_context->swapBuffers(m_window);
    m_presentedSize = windowPixels();
    m_lastPresentedAt = std::chrono::steady_clock::now();
    emit frameSwapped();
}

void ViewportSurface::framePresented(quint64 loan, double drawMs, qint64 swappedNs, bool ok)
{
    // The presenter gave the context back before it said so. Only its loan
    // ends here: if this thread took the context back meanwhile and lent it
    // on (a warm-up), that loan is not this frame's to end.
    if (m_presenter && m_lender.borrower() == m_presenter->presenterThread()
        && loan == m_presentLoans)
        takeBackContext();
    if (!ok) {
        // The context cannot be made current off this thread here: present
        // on this thread from now on.
        qWarning("phonglab: frames cannot be presented from a thread of their own; the GUI "
                 "thread presents them");
        m_presenter.reset();
        requestFrame();
        return;
    }
    bookPresented(
        drawMs,
        std::chrono::steady_clock::time_point(std::chrono::steady_clock::duration(swappedNs)),
        windowPixels(), /*fromLoan=*/false);
}

// A frame another thread drew and swapped (the presenter, or a borrower
// with a LoanFrame), booked as this thread's own are.
void ViewportSurface::bookPresented(double drawMs, std::chrono::steady_clock::time_point swappedAt,
                                    const QSize &backBuffer, bool fromLoan)
{
    // A frame this thread presented meanwhile is the newer one.
    if (swappedAt > m_lastPresentedAt) {
        m_lastPresentedAt = swappedAt;
        m_presentedSize = backBuffer;
    }
    frameDrawn(drawMs, fromLoan);
    emit frameSwapped();
}

QImage ViewportSurface::grabFrame()
{
    takeBackContext();
    if (!isStarted() || !m_window->handle())
        return {};
    makeCurrent();
    QOpenGLFunctions *f = m_context->functions();
    f->glBindFramebuffer(GL_FRAMEBUFFER, m_context->defaultFramebufferObject());
    if (m_presentedSize != windowPixels()) {
        // The back buffer may still have the size before a resize: present
        // a frame first, which gives it the window's.
        m_content->drawScene(pixels());
        m_context->swapBuffers(m_window);
        m_presentedSize = windowPixels();
    }
    const auto started = std::chrono::steady_clock::now();
    if (m_content->drawScene(pixels())) {
        f->glFinish(); // without it the time would be the submission's
        frameDrawn(msSince(started));
    }
    m_content->drawOverlays(pixels());
    QImage image = readBackBuffer(pixels()).convertToFormat(QImage::Format_RGB32);
    doneCurrent();
    image.setDevicePixelRatio(m_view->devicePixelRatioF());
    return image;
}

QImage ViewportSurface::readBackBuffer(const QSize &pixels)
{
    QImage image(pixels, QImage::Format_RGBA8888);
    QOpenGLExtraFunctions *f = m_context->extraFunctions();
    f->glBindFramebuffer(GL_READ_FRAMEBUFFER, m_context->defaultFramebufferObject());
    f->glReadBuffer(GL_BACK);
    f->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    f->glReadPixels(0, 0, pixels.width(), pixels.height(), GL_RGBA, GL_UNSIGNED_BYTE, image.bits());
    return image.mirrored();
}

void ViewportSurface::frameDrawn(double drawMs, bool fromLoan)
{
    const auto now = std::chrono::steady_clock::now().time_since_epoch();
    if (m_ledger.book(std::chrono::duration_cast<std::chrono::nanoseconds>(now).count(), drawMs,
                      fromLoan))
        emit framesHeldAfter(drawMs);
    emit frameTimed(m_ledger.times().meanMs());
}

void ViewportSurface::resumeFrames()
{
    if (m_ledger.resume())
        requestFrame();
}

} // namespace phonglab
