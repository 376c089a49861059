#include "OffscreenRenderer.h"

#include "headless/HeadlessPlatform.h"
#include "render/gl/GlFormat.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QGuiApplication>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFunctions>
#include <QOpenGLTimerQuery>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct OffscreenRendererWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::OffscreenRenderer)
};

namespace {

// Names what is missing: the EGL platform's own reason without a display
// server, else the display's driver.
QString noContextMessage()
{
    if (runsHeadless())
        return OffscreenRendererWords::tr(
                   "no OpenGL context could be created without a display server: %1. "
                   "PhongLab renders through EGL there (Mesa: packages libegl1 and "
                   "libegl-mesa0), or under an X server (`xvfb-run -a phonglab ...`)")
            .arg(headlessGlProblem());
    const QString display = qEnvironmentVariable("DISPLAY");
    return OffscreenRendererWords::tr(
               "no OpenGL context could be created on Qt's '%1' platform%2; "
               "QT_QPA_PLATFORM=phonglab-headless renders through EGL without a "
               "display server")
        .arg(QGuiApplication::platformName(),
             display.isEmpty() ? QString() : QStringLiteral(" (DISPLAY=%1)").arg(display));
}

} // namespace

OffscreenRenderer::OffscreenRenderer() = default;

OffscreenRenderer::~OffscreenRenderer()
{
    destroy();
}

Result<> OffscreenRenderer::create(QOffscreenSurface *surface)
{
    const QSurfaceFormat format = phonglabSurfaceFormat(0);
    m_context = std::make_unique<QOpenGLContext>();
    m_context->setFormat(format);
    if (!m_context->create()) {
        m_context.reset();
        return fail(noContextMessage());
    }
    const QSurfaceFormat got = m_context->format();
    if (got.version() < qMakePair(3, 3)) {
        m_context.reset();
        return fail(OffscreenRendererWords::tr("OpenGL 3.3 is required, the driver offers %1.%2")
                        .arg(got.majorVersion())
                        .arg(got.minorVersion()));
    }
    if (surface) {
        m_surface = surface;
    } else {
        m_ownSurface = std::make_unique<QOffscreenSurface>();
        m_ownSurface->setFormat(got);
        m_ownSurface->create();
        m_surface = m_ownSurface.get();
    }
    if (!m_context->makeCurrent(m_surface)) {
        destroy();
        return fail(OffscreenRendererWords::tr(
            "the OpenGL context could not be made current on an offscreen surface"));
    }
    m_rendererName = QString::fromLatin1(
        reinterpret_cast<const char *>(m_context->functions()->glGetString(GL_RENDERER)));
    return m_renderer.initialize();
}

void OffscreenRenderer::makeCurrent()
{
    if (m_context)
        m_context->makeCurrent(m_surface);
}

QImage OffscreenRenderer::renderImage(const QSize &size)
{
    if (!m_context || size.isEmpty())
        return {};
    bindTarget(size);
    m_renderer.render(size);
    m_context->functions()->glFinish();
    // Flipped to raster order (row 0 on top). Alpha is 1 everywhere, so the
    // premultiplied format changes no colour value.
    QImage image = m_fbo->toImage(true);
    m_fbo->release();
    return image.convertToFormat(QImage::Format_RGB888);
}

std::vector<float> OffscreenRenderer::renderFloatPixels(const QSize &size)
{
    if (!m_context || size.isEmpty())
        return {};
    bindFloatTarget(size);
    m_renderer.render(size);
    QOpenGLFunctions *gl = m_context->functions();
    std::vector<float> rows(std::size_t(size.width()) * size.height() * 4);
    gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    gl->glReadPixels(0, 0, size.width(), size.height(), GL_RGBA, GL_FLOAT, rows.data());
    m_floatFbo->release();
    // GL's rows run bottom-up.
    std::vector<float> pixels(rows.size());
    const std::size_t stride = std::size_t(size.width()) * 4;
    for (int y = 0; y < size.height(); ++y)
        std::copy_n(rows.begin() + std::ptrdiff_t(stride * (size.height() - 1 - y)), stride,
                    pixels.begin() + std::ptrdiff_t(stride * y));
    return pixels;
}

void OffscreenRenderer::bindFloatTarget(const QSize &size)
{
    makeCurrent();
    if (!m_floatFbo || m_floatFbo->size() != size) {
        QOpenGLFramebufferObjectFormat format;
        format.setAttachment(QOpenGLFramebufferObject::Depth);
        format.setInternalTextureFormat(GL_RGBA32F);
        format.setSamples(0);
        m_floatFbo = std::make_unique<QOpenGLFramebufferObject>(size, format);
    }
    m_floatFbo->bind();
}

void OffscreenRenderer::bindTarget(const QSize &size)
{
    makeCurrent();
    if (!m_fbo || m_fbo->size() != size) {
        QOpenGLFramebufferObjectFormat format;
        format.setAttachment(QOpenGLFramebufferObject::Depth);
        format.setInternalTextureFormat(GL_RGBA8);
        format.setSamples(0);
        m_fbo = std::make_unique<QOpenGLFramebufferObject>(size, format);
    }
    m_fbo->bind();
}

FrameTiming OffscreenRenderer::timeFrames(const QSize &size, int warmup, int frames)
{
    FrameTiming timing;
    if (!m_context || size.isEmpty() || frames <= 0)
        return timing;
    bindTarget(size);
    QOpenGLFunctions *gl = m_context->functions();
    for (int i = 0; i < warmup; ++i) {
        m_renderer.render(size);
        gl->glFinish();
    }
    std::vector<double> wall, submit;
    wall.reserve(std::size_t(frames));
    submit.reserve(std::size_t(frames));
    for (int i = 0; i < frames; ++i) {
        QElapsedTimer timer;
        timer.start();
        m_renderer.render(size);
        submit.push_back(timer.nsecsElapsed() / 1e6);
        gl->glFinish();
        wall.push_back(timer.nsecsElapsed() / 1e6);
    }
    timing.wallMedianMs = medianOf(wall);
    timing.wallP90Ms = percentileOf(wall, 0.9);
    timing.cpuSubmitMedianMs = medianOf(submit);
    timing.frames = frames;
    if (timerQueryTrusted(m_rendererName))
        timing.gpuMedianMs = medianOf(timerQueryFrames(size, frames));
    m_fbo->release();
    return timing;
}

// GL_TIME_ELAPSED around each frame, a separate pass so the queries do not
// disturb the wall-time figures. Empty when the driver lacks the entry points.
std::vector<double> OffscreenRenderer::timerQueryFrames(const QSize &size, int frames)
{
    std::vector<double> ms;
    QOpenGLTimerQuery query;
    if (!query.create())
        return ms;
    for (int i = 0; i < frames; ++i) {
        query.begin();
        m_renderer.render(size);
        query.end();
        ms.push_back(double(query.waitForResult()) / 1e6);
    }
    return ms;
}

void OffscreenRenderer::destroy()
{
    if (!m_context)
        return;
    if (m_surface)
        m_context->makeCurrent(m_surface);
    m_renderer.cleanup();
    m_fbo.reset();
    m_floatFbo.reset();
    m_context->doneCurrent();
    m_context.reset();
    m_surface = nullptr;
    m_ownSurface.reset();
}

} // namespace phonglab
