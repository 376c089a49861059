#include "FramebufferImage.h"

#include "Renderer.h"

#include <QOpenGLFramebufferObject>
#include <algorithm>

namespace phonglab {

QImage drawIntoImage(Renderer &renderer, const QSize &pixelSize, int samples)
{
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    format.setInternalTextureFormat(GL_RGBA8);
    format.setSamples(std::max(0, samples));
    QOpenGLFramebufferObject target(pixelSize, format);
    if (!target.isValid() || !target.bind())
        return {};
    renderer.render(pixelSize);
    target.release();
    if (format.samples() == 0)
        return target.toImage(true);
    QOpenGLFramebufferObjectFormat resolvedFormat;
    resolvedFormat.setInternalTextureFormat(GL_RGBA8);
    QOpenGLFramebufferObject resolved(pixelSize, resolvedFormat);
    QOpenGLFramebufferObject::blitFramebuffer(&resolved, &target);
    return resolved.toImage(true);
}

} // namespace phonglab
