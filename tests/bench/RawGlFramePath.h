#pragma once
#include "RawGlCalls.h"
#include "core/scene/Scene.h"
#include "mesh/loading/SceneMeshes.h"

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

    // How the frame reaches the window. Direct: drawn into the window's own
    // multisampled framebuffer, as a plain GL program does. ThroughTexture:
    // the steps QOpenGLWidget and Qt's window composition take, in plain
    // GL: drawn into a multisampled framebuffer object, resolved into a
    // texture; the widgets' backing store (a texture the size of the whole
    // window) gets the view's region uploaded, is drawn over the window, and
    // the view's texture over it; the window itself has no samples.
    enum class Presentation {
        Direct,
        ThroughTexture
    };

    // Opens the window and uploads the meshes; false after saying why on
    // stderr. `size` is the view's size in device pixels; ThroughTexture
    // makes the window `windowSize` (the main window's) with the view in its
    // top-left corner.
    bool create(const QSize &size, int samples, const Scene &scene, const SceneMeshes &meshes,
                Placement placement = Placement::OwnWindow,
                Presentation presentation = Presentation::Direct, QSize windowSize = {});
    // Draws and presents one frame; the wall time from its first GL call to
    // swapBuffers returning, in milliseconds.
    double drawFrame();

    // One frame with glFinish after every step, so that each step's time is
    // its own (ms). The finishes serialise the frame: these add up to more
    // than drawFrame() takes, and say where the time goes, not the frame.
    struct Steps {
        double draw = 0;    // the scene into the multisampled target
        double resolve = 0; // samples into the view's texture (ThroughTexture)
        double upload = 0;  // the view's region into the backing store texture
        double compose = 0; // both textures drawn into the window
        double swap = 0;    // swapBuffers (Direct: the resolve happens here)
    };
    Steps drawTimedFrame();

private:
    bool createComposition(int samples);
    void drawScene();
    void resolve();
    void uploadLayer();
    void compose();

    struct Object {
        RawMesh mesh;
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
    Presentation m_presentation = Presentation::Direct;
    QSize m_windowSize;
    // ThroughTexture's objects: the multisampled target, the view's
    // texture, the backing store's texture and the program drawing both.
    GLuint m_sampledFbo = 0, m_sampledColor = 0, m_sampledDepth = 0;
    GLuint m_viewFbo = 0, m_viewTexture = 0, m_layerTexture = 0;
    GLuint m_quadProgram = 0, m_quadVao = 0;
    std::vector<unsigned char> m_layerPixels; // what the backing store holds for the view
};

} // namespace phonglab::bench
