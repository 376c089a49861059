// Viewport's frames: drawing, presenting (on this thread or the
// presenter's), the widgets drawn over them, and reading them back (the
// rest of the class is in Viewport.cpp).
#include "Viewport.h"

#include "CurrentContext.h"
#include "FramePresenter.h"
#include "ViewportWindow.h"
#include "render/FramebufferImage.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFunctions>
#include <QPainter>
#include <chrono>
#include <utility>

namespace phonglab {

namespace {

double msSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

} // namespace

QSize Viewport::windowPixels() const
{
    return m_window->size() * m_window->devicePixelRatio();
}

QImage Viewport::grabFramebuffer()
{
    takeBackContext();
    if (!m_context || !m_context->isValid() || !m_window->handle())
        return {};
    makeCurrent();
    if (m_presentedSize != windowPixels()) {
        // The back buffer may still have the size before a resize: present
        // a frame first, which gives it the window's.
        drawScene();
        m_context->swapBuffers(m_window);
        m_presentedSize = windowPixels();
    }
    const auto started = std::chrono::steady_clock::now();
    if (drawScene()) {
        m_context->functions()->glFinish(); // without it the time would be the submission's
        frameDrawn(msSince(started));
    }
    drawOverlays();
    QImage image = readBackBuffer(pixelSize()).convertToFormat(QImage::Format_RGB32);
    doneCurrent();
    image.setDevicePixelRatio(devicePixelRatioF());
    return image;
}

// Needs the context current: the bottom-left `pixels` of the window's back
// buffer, resolved by the read, top row first.
QImage Viewport::readBackBuffer(const QSize &pixels)
{
    QImage image(pixels, QImage::Format_RGBA8888);
    QOpenGLExtraFunctions *f = m_context->extraFunctions();
    f->glBindFramebuffer(GL_READ_FRAMEBUFFER, m_context->defaultFramebufferObject());
    f->glReadBuffer(GL_BACK);
    f->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    f->glReadPixels(0, 0, pixels.width(), pixels.height(), GL_RGBA, GL_UNSIGNED_BYTE, image.bits());
    return image.mirrored();
}

// Every child widget but the window's container lies over the frame and is
// drawn into it: a change to one is a new frame.
void Viewport::childEvent(QChildEvent *event)
{
    if (event->added() && event->child()->isWidgetType())
        event->child()->installEventFilter(this);
    QWidget::childEvent(event);
}

bool Viewport::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_container)
        return false;
    switch (event->type()) {
    case QEvent::Paint:
        if (m_paintingOverlays)
            break;
        [[fallthrough]];
    case QEvent::Show:
    case QEvent::Hide:
    case QEvent::Move:
    case QEvent::Resize:
        m_overlayDirty = true;
        requestFrame();
        break;
    default: break;
    }
    return false;
}

QImage Viewport::renderImage(const QSize &pixelSize, bool lightMarkers)
{
    if (!m_renderReady || pixelSize.isEmpty())
        return {};
    const CurrentContext current(*this);
    sendChangedParameters();
    Renderer::Options options = m_options;
    options.drawLightMarkers = options.drawLightMarkers && lightMarkers;
    m_renderer.setOptions(options);
    // Up to the window's size (the live check): drawn into a corner of the
    // window's back buffer, the framebuffer whose shader variant the lent
    // warm-up compiled off the GUI thread; any other framebuffer would cost
    // llvmpipe another compile here, ~80 ms after every edit. Larger (an
    // export): a framebuffer object with the view's samples.
    const QSize window = windowPixels();
    // A window resized since its last frame may still have a back buffer
    // of the old size (Mesa takes the new one at the next swap).
    const bool inWindow = m_window->isExposed() && m_presentedSize == window
        && pixelSize.width() <= window.width() && pixelSize.height() <= window.height();
    QImage image;
    if (inWindow) {
        m_context->functions()->glBindFramebuffer(GL_FRAMEBUFFER,
                                                  m_context->defaultFramebufferObject());
        m_renderer.render(pixelSize);
        // What is on screen stays: every frame redraws the whole back buffer
        // before it swaps.
        image = readBackBuffer(pixelSize).convertToFormat(QImage::Format_RGB32);
    } else {
        image = drawIntoImage(m_renderer, pixelSize, m_framebufferSamples);
    }
    m_renderer.setOptions(m_options);
    return image;
}

void Viewport::drawFrame()
{
    if (m_framesHeld) {
        ++m_framesRefused;
        return; // resumeFrames() asks for the frame
    }

    if (m_lender.isActive()) {
        m_frameMissed = true;
        return;
    }
    if (!m_window->isExposed())
        return;
    if (!m_context)
        startGl();
    if (!m_context->isValid() || !m_context->makeCurrent(m_window))
        return;
    const auto started = std::chrono::steady_clock::now();
    const bool scene = drawScene();
    drawOverlays();
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
        m_context->functions()->glFinish(); // without it the time would be the submission's
        frameDrawn(msSince(started));
    }
    m_context->swapBuffers(m_window);
    m_presentedSize = windowPixels();
    m_lastPresentedAt = std::chrono::steady_clock::now();
    emit frameSwapped();
}

void Viewport::framePresented(quint64 loan, double drawMs, qint64 swappedNs, bool ok)
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
    m_lastPresentedAt =
        std::chrono::steady_clock::time_point(std::chrono::steady_clock::duration(swappedNs));
    m_presentedSize = windowPixels();
    frameDrawn(drawMs);
    emit frameSwapped();
}

// Once, on the first exposure: the context for the window's format, sharing
// objects with the rest of the application (the build thread's context).
void Viewport::startGl()
{
    m_context = std::make_unique<QOpenGLContext>();
    m_context->setFormat(m_window->requestedFormat());
    m_context->setShareContext(QOpenGLContext::globalShareContext());
    if (!m_context->create() || !m_context->makeCurrent(m_window)) {
        emit renderError(tr("Cannot create an OpenGL context for the viewport"));
        m_context = std::make_unique<QOpenGLContext>(); // invalid: no second try
        return;
    }
    if (m_mayPresentOffThread && QOpenGLContext::supportsThreadedOpenGL()) {
        m_presenter = std::make_unique<FramePresenter>();
        connect(m_presenter.get(), &FramePresenter::presented, this, &Viewport::framePresented,
                Qt::QueuedConnection);
    }
    initializeGl();
}

// Needs the context current: the scene into the window's back buffer.
bool Viewport::drawScene()
{
    QOpenGLFunctions *f = context()->functions();
    f->glBindFramebuffer(GL_FRAMEBUFFER, m_context->defaultFramebufferObject());
    if (!m_renderReady) {
        // Nothing to draw (GL failed and was reported): show the background.
        const glm::dvec3 bg = m_scene.background;
        f->glClearColor(float(bg.r), float(bg.g), float(bg.b), 1.0f);
        f->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return false;
    }
    sendChangedParameters();
    if (m_framebufferSamples < 0) {
        // What the window really got, not what was asked for: a warm-up
        // must draw with the same.
        f->glGetIntegerv(GL_SAMPLES, &m_framebufferSamples);
    }
    m_renderer.render(pixelSize());
    return true;
}

void Viewport::frameDrawn(double drawMs)
{
    const auto now = std::chrono::steady_clock::now().time_since_epoch();
    m_frameTimes.add(std::chrono::duration_cast<std::chrono::nanoseconds>(now).count(), drawMs);
    ++m_framesRendered;
    if (drawMs > kHoldFramesAfterMs && !m_framesHeld) {
        m_framesHeld = true;
        emit framesHeldAfter(drawMs);
    }
    emit frameRendered(m_frameTimes.meanMs(), m_renderer.trianglesDrawn());
}

void Viewport::resumeFrames()
{
    if (!m_framesHeld)
        return;
    m_framesHeld = false;
    requestFrame();
}

// Needs the context current: the visible child widgets over the frame, as
// QPainter draws them (premultiplied), painted again only when one changed.
void Viewport::drawOverlays()
{
    QList<QWidget *> shown;
    for (QWidget *child : findChildren<QWidget *>(Qt::FindDirectChildrenOnly))
        if (child != m_container && child->isVisible())
            shown << child;
    if (shown.isEmpty())
        return;
    const QSize pixels = pixelSize();
    if (m_overlayDirty || m_overlayImage.size() != pixels) {
        QImage image(pixels, QImage::Format_RGBA8888_Premultiplied);
        image.setDevicePixelRatio(devicePixelRatioF());
        image.fill(Qt::transparent);
        m_paintingOverlays = true;
        {
            QPainter painter(&image);
            for (QWidget *child : shown)
                child->render(&painter, child->pos(), QRegion(), QWidget::DrawChildren);
        }
        m_paintingOverlays = false;
        m_overlayImage = image;
        m_overlayDirty = false;
    }
    m_overlayLayer.draw(m_overlayImage, pixels);
}

} // namespace phonglab
