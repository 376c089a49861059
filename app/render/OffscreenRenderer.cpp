#include "OffscreenRenderer.h"

#include "GlFormat.h"

#include <QOpenGLFunctions>

namespace phonglab {

OffscreenRenderer::OffscreenRenderer() = default;

OffscreenRenderer::~OffscreenRenderer()
{
    destroy();
}

bool OffscreenRenderer::create(QString *error)
{
    const QSurfaceFormat format = phonglabSurfaceFormat(0);
    m_context = std::make_unique<QOpenGLContext>();
    m_context->setFormat(format);
    if (!m_context->create()) {
        if (error)
            *error = QStringLiteral("no OpenGL context could be created (no display or driver; "
                                    "run under an X server, e.g. `xvfb-run -a phonglab ...`)");
        m_context.reset();
        return false;
    }
    const QSurfaceFormat got = m_context->format();
    if (got.version() < qMakePair(3, 3)) {
        if (error)
            *error = QStringLiteral("OpenGL 3.3 is required, the driver offers %1.%2")
                         .arg(got.majorVersion()).arg(got.minorVersion());
        m_context.reset();
        return false;
    }
    m_surface = std::make_unique<QOffscreenSurface>();
    m_surface->setFormat(got);
    m_surface->create();
    if (!m_context->makeCurrent(m_surface.get())) {
        if (error)
            *error = QStringLiteral("the OpenGL context could not be made current on an offscreen surface");
        destroy();
        return false;
    }
    m_rendererName = QString::fromLatin1(
        reinterpret_cast<const char *>(m_context->functions()->glGetString(GL_RENDERER)));
    return m_renderer.initialize(error);
}

void OffscreenRenderer::makeCurrent()
{
    if (m_context)
        m_context->makeCurrent(m_surface.get());
}

QImage OffscreenRenderer::renderImage(const QSize &size)
{
    if (!m_context || size.isEmpty())
        return {};
    makeCurrent();
    if (!m_fbo || m_fbo->size() != size) {
        QOpenGLFramebufferObjectFormat format;
        format.setAttachment(QOpenGLFramebufferObject::Depth);
        format.setInternalTextureFormat(GL_RGBA8);
        format.setSamples(0);
        m_fbo = std::make_unique<QOpenGLFramebufferObject>(size, format);
    }
    m_fbo->bind();
    m_renderer.render(size);
    m_context->functions()->glFinish();
    // Flipped to raster order (row 0 on top). Alpha is 1 everywhere, so the
    // premultiplied format changes no colour value.
    QImage image = m_fbo->toImage(true);
    m_fbo->release();
    return image.convertToFormat(QImage::Format_RGB888);
}

void OffscreenRenderer::destroy()
{
    if (!m_context)
        return;
    if (m_surface)
        m_context->makeCurrent(m_surface.get());
    m_renderer.cleanup();
    m_fbo.reset();
    m_context->doneCurrent();
    m_context.reset();
    m_surface.reset();
}

} // namespace phonglab
