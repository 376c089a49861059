#pragma once
#include "core/Scene.h"
#include "mesh/SceneMeshes.h"

#include <QMainWindow>
#include <QOpenGLContext>
#include <QSize>
#include <QWindow>
#include <memory>
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

    // A window of its own, or a native child window (QWidget::
    // createWindowContainer) inside a main window with a dock and a status
    // bar, as PhongLab's window has: that window's widgets are composed by
    // the window system, not redrawn with every GL frame.
    enum class Placement {
        OwnWindow,
        InsideMainWindow
    };

    // Opens the window at `size` (device pixels) and uploads the meshes;
    // false after saying why on stderr.
    bool create(const QSize &size, int samples, const Scene &scene, const SceneMeshes &meshes,
                Placement placement = Placement::OwnWindow);
    // Draws and presents one frame; the wall time from its first GL call to
    // swapBuffers returning, in milliseconds.
    double drawFrame();

private:
    struct Object {
        GLuint vao = 0, vbo = 0, ibo = 0;
        GLsizei indexCount = 0;
        bool cull = false;
    };

    std::unique_ptr<QMainWindow> m_host; // owns m_window when inside it
    std::unique_ptr<QWindow> m_ownWindow;
    QWindow *m_window = nullptr;
    QOpenGLContext m_context;
    Scene m_scene;
    QSize m_size;
    GLuint m_program = 0;
    std::vector<Object> m_objects;
};

} // namespace phonglab::bench
