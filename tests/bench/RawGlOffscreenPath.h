#pragma once
#include "RawGlCalls.h"
#include "core/scene/MeshData.h"
#include "core/scene/Scene.h"

#include <QSize>
#include <QtGui/qopengl.h>

namespace phonglab::bench {

// The floor PhongLab's offscreen frame is measured against: the same mesh
// drawn with the shipped Phong program through plain GL calls (no Qt
// wrappers, no renderer), into a framebuffer object of the format
// OffscreenRenderer draws into (RGBA8 colour texture, depth renderbuffer,
// no multisampling), timed as OffscreenRenderer::timeFrames() times its
// frames: wall clock from the first call to glFinish returning.
//
// Uses whatever context is current (the OffscreenRenderer's, so both paths
// run on the same driver state); every call needs it current.
class RawGlOffscreenPath
{
public:
    RawGlOffscreenPath() = default;
    ~RawGlOffscreenPath();
    RawGlOffscreenPath(const RawGlOffscreenPath &) = delete;
    RawGlOffscreenPath &operator=(const RawGlOffscreenPath &) = delete;

    // Builds the shipped Phong program; false after saying why on stderr.
    bool create();
    // Uploads `mesh` (interleaved position + normal, 32-bit indices), in
    // place of the one before, to be drawn as `scene`'s first object.
    void setMesh(const MeshData &mesh, const Scene &scene);
    // Draws `warmup` frames, then `frames` timed ones; the median, ms.
    double timeFrames(const QSize &size, int warmup, int frames);
    // The share of the image that is not background, from one frame read
    // back: the check that the frame draws what PhongLab's does.
    double coveredShare(const QSize &size);

private:
    void bindTarget(const QSize &size);
    void drawFrame();
    void deleteTarget();

    Scene m_scene;
    QSize m_size;
    GLuint m_program = 0;
    RawMesh m_mesh;
    GLuint m_fbo = 0, m_color = 0, m_depth = 0;
};

} // namespace phonglab::bench
