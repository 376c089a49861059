#pragma once
#include "core/Scene.h"
#include "mesh/SceneMeshes.h"

#include <QOpenGLContext>
#include <QSize>
#include <QWindow>
#include <vector>

namespace phonglab::bench {

// The floor a viewport frame is measured against: a plain window (QWindow +
// QOpenGLContext, no widgets) drawing every object of the scene with the
// shipped Phong program through plain GL calls, into a default framebuffer
// with the viewport's MSAA samples, and presenting it (swapBuffers): a frame
// that reaches the screen, as the viewport's does.
class RawGlFramePath
{
public:
    RawGlFramePath() = default;
    ~RawGlFramePath();
    RawGlFramePath(const RawGlFramePath &) = delete;
    RawGlFramePath &operator=(const RawGlFramePath &) = delete;

    // Opens the window at `size` (device pixels) and uploads the meshes;
    // false after saying why on stderr.
    bool create(const QSize &size, int samples, const Scene &scene, const SceneMeshes &meshes);
    // Draws and presents one frame; the wall time from its first GL call to
    // swapBuffers returning, with glFinish after, in milliseconds.
    double drawFrame();

private:
    struct Object {
        GLuint vao = 0, vbo = 0, ibo = 0;
        GLsizei indexCount = 0;
        bool cull = false;
    };
    GLuint compile(GLenum type, const QByteArray &text);

    QWindow m_window;
    QOpenGLContext m_context;
    Scene m_scene;
    QSize m_size;
    GLuint m_program = 0;
    std::vector<Object> m_objects;
};

} // namespace phonglab::bench
