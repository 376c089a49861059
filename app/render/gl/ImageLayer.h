#pragma once
#include <QImage>
#include <QOpenGLExtraFunctions>
#include <QSize>

namespace phonglab {

// Draws an image over the frame in the current framebuffer, blended by its
// alpha: how the viewport shows the widgets that lie over it (the check's
// pictures, the detail label) now that its frame goes straight to its window
// and Qt no longer composes widgets over it. Needs the context current for
// every call; destroy() before the context goes.
class ImageLayer : protected QOpenGLExtraFunctions
{
public:
    ImageLayer() = default;
    ImageLayer(const ImageLayer &) = delete;
    ImageLayer &operator=(const ImageLayer &) = delete;

    // `image` (premultiplied ARGB, the size of the frame in pixels) over the
    // whole viewport of `pixelSize`. The texture is uploaded again only when
    // the image changed (QImage::cacheKey). Leaves blending and depth
    // testing off.
    void draw(const QImage &image, const QSize &pixelSize);
    void destroy();

private:
    bool create();

    GLuint m_program = 0;
    GLuint m_vao = 0;
    GLuint m_texture = 0;
    qint64 m_uploadedKey = 0;
    bool m_failed = false; // the program did not build: draw nothing, once said
};

} // namespace phonglab
