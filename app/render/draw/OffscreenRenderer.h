#pragma once
#include "FrameTiming.h"
#include "Renderer.h"
#include "core/support/Result.h"

#include <QImage>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <memory>

namespace phonglab {

// Headless rendering: its own context on a QOffscreenSurface, drawing into an
// 8-bit RGBA framebuffer object without multisampling, so every pixel is
// round(clamp(I, 0, 1) · 255) of exactly one fragment. Used by
// `phonglab render`, the benchmarks and the GL tests.
class OffscreenRenderer
{
public:
    OffscreenRenderer();
    ~OffscreenRenderer();

    // Creates the context. A failure when no OpenGL 3.3 context can be had
    // (no display, no driver). With `surface` (not owned; it must outlive
    // this and be of phonglabSurfaceFormat(0)) the context is made for it:
    // off the GUI thread, where Qt cannot create a surface, a caller makes
    // one on the GUI thread and hands it over.
    Result<> create(QOffscreenSurface *surface = nullptr);

    // Must be called with nothing else current on this thread; makes the
    // context current and leaves it so.
    Renderer &renderer() { return m_renderer; }
    void makeCurrent();

    // Renders the renderer's current scene and reads it back as RGB888.
    QImage renderImage(const QSize &size);
    // The same into a 32-bit float target, read back unclamped: a NaN or
    // an infinity a shader wrote is seen, where 8 bits would clamp it away.
    // RGBA floats in raster order (row 0 on top); empty on failure.
    std::vector<float> renderFloatPixels(const QSize &size);

    // Draws `warmup` frames, then times `frames` more at `size` (see
    // FrameTiming for what is measured and why).
    FrameTiming timeFrames(const QSize &size, int warmup, int frames);

    QString glRendererName() const { return m_rendererName; }

private:
    void destroy();
    void bindTarget(const QSize &size);
    void bindFloatTarget(const QSize &size);
    std::vector<double> timerQueryFrames(const QSize &size, int frames);

    std::unique_ptr<QOpenGLContext> m_context;
    std::unique_ptr<QOffscreenSurface> m_ownSurface;
    QOffscreenSurface *m_surface = nullptr; // m_ownSurface, or the caller's
    std::unique_ptr<QOpenGLFramebufferObject> m_fbo;
    std::unique_ptr<QOpenGLFramebufferObject> m_floatFbo;
    Renderer m_renderer;
    QString m_rendererName;
};

} // namespace phonglab
