#pragma once
#include "ContextLender.h"
#include "core/FrameTimeWindow.h"
#include "core/OrbitCamera.h"
#include "core/Scene.h"
#include "render/ImageLayer.h"
#include "render/LentContext.h"
#include "render/ProgramBuilder.h"
#include "render/Renderer.h"
#include "render/UniformSnapshot.h"
#include "render/WarmUpDraw.h"

#include <QImage>
#include <QOpenGLContext>
#include <QPointF>
#include <QWidget>
#include <chrono>
#include <memory>
#include <optional>

namespace phonglab {

class FramePresenter;
class ViewportWindow;

// A frame that took longer than this is not drawn again by itself: the view
// waits until the user acts on it (issue 31, C).
inline constexpr double kHoldFramesAfterMs = 250.0;

// The interactive 3D view: drives a Renderer and turns mouse and keyboard
// input into OrbitCamera moves. Left drag orbits, right or middle drag pans,
// the wheel zooms. Keys are the shortcuts of the actions added to it (the
// window's Reset Camera: R, Home).
//
// Its frames go to a native window of their own (ViewportWindow, in a window
// container filling this widget) and are presented with swapBuffers, as a
// plain GL program's are; a QOpenGLWidget's frame costs a resolve and a
// composition of the whole main window on top (docs/performance.md). Child
// widgets of the view (the check's pictures, the detail label) are drawn
// over each frame in GL.
class Viewport : public QWidget
{
    Q_OBJECT

public:
    // presentOffThread: the wait for the rasteriser and the swap on a thread
    // of their own where the platform allows it (StartupOptions can say no).
    explicit Viewport(QWidget *parent = nullptr, bool presentOffThread = true);
    ~Viewport() override;

    // Shows `scene` with its own camera. On failure (a mesh that cannot be
    // loaded, a shading program that does not build) the current scene stays
    // and the failure says why. Loads the meshes on the calling thread: the
    // window uses SceneLoadJob and the overload below instead.
    Result<> setScene(const Scene &scene);
    // Shows `scene` with meshes loaded elsewhere (loadSceneMeshes(scene,
    // loadedKeys())). Before GL starts (the first exposure) they wait there.
    Result<> setScene(const Scene &scene, SceneMeshes &&meshes);
    // Meshes already on the GPU, which a load may skip (by meshKey()).
    QSet<QString> loadedKeys() const;
    // Statistics and warnings of the meshes the scene uses, by meshKey().
    const QHash<QString, SceneMeshes::Entry> &meshInfo() const;
    // The scene as shown, with the orbited camera in place of the original.
    Scene currentScene() const;
    const Camera &camera() const { return m_orbit.camera(); }
    // What Save writes: the scene's own camera until the user moves it (a
    // camera moved back only to fit this view's shape is not the scene's),
    // the moved one after, marked as a shot to keep (frameObjects false).
    Camera cameraToSave() const;

    // The scene's shading method changes without touching the program: the
    // live shader controller builds it (so Save writes the preset in use).
    void setShading(ShadingMethod method);

    // Programs built elsewhere. adoptProgram() switches to a program linked
    // on a context sharing this one's objects (or by buildProgram()) and owns
    // it from then on; uniforms the user set carry over. buildProgram()
    // compiles on the GUI thread with this context: the fallback when no
    // shared context can be had. Both need GL to be up (glInitialized()).
    void adoptProgram(GlProgram program);
    BuiltProgram buildProgram(const ShaderSource &vertex, const ShaderSource &fragment);
    Renderer &renderer() { return m_renderer; } // call with the context current (CurrentContext)
    // The near/far planes of the last frame (no GL call; any time).
    const DepthRange &depthRange() const { return m_renderer.depthRange(); }

    // Lends the GL context to `borrower` (see LentContext), so that a new
    // program's draw-time compile happens in this very context but off the
    // GUI thread. Until takeBackContext() the view does not paint, and anything that
    // needs the context on this thread first waits for it to come back.
    // Waits for a frame being presented first. Refused (nullopt) before GL
    // is up: the caller then does the work itself.
    std::optional<LentContext> lendContext(QThread *borrower);
    // Waits for a lent context (at most timeoutMs; -1: as long as it takes)
    // and paints again. False if it did not come back in time.
    bool takeBackContext(int timeoutMs = -1);
    bool isContextLent() const { return m_lender.isActive(); }
    // Samples of the framebuffer the view draws into (-1 before the first frame).
    int framebufferSamples() const { return m_framebufferSamples; }
    // A frame drawn now (overlays included) and read back, once a lent
    // context is back; null before the window was first shown.
    QImage grabFramebuffer();

    // The view's GL context (null before the window was first shown);
    // makeCurrent() and doneCurrent() as QOpenGLWidget's.
    QOpenGLContext *context() const { return m_context.get(); }
    void makeCurrent();
    void doneCurrent();
    // The format the view's window asks for (samples, depth); set before the
    // window is first shown.
    void setFormat(const QSurfaceFormat &format);
    QSurfaceFormat format() const;
    // A new frame at the next turn of the event loop (QWidget::update()
    // repaints only the widget around the view's window).
    void requestFrame();
    // The native window the frames go to; its input reaches this widget.
    QWindow *frameWindow() const;
    // When the last frame was handed to the window system (swapBuffers
    // returned), on whichever thread presented it.
    std::chrono::steady_clock::time_point lastPresentedAt() const { return m_lastPresentedAt; }

    // The cheap path for dock edits: takes lights, ambient, materials and
    // transforms from `scene` (same objects and meshes as shown) without
    // reloading anything; the camera as orbited stays.
    void setSceneParameters(const Scene &scene);
    // The current frame rendered again at `pixelSize` with this view's
    // renderer, program and samples (File → Export Image; the live check
    // draws its own, single-sampled: FrameRedraw).
    // Null when GL is not up or the size cannot be allocated. Without
    // `lightMarkers` the frame is the scene alone (what a check compares).
    QImage renderImage(const QSize &pixelSize, bool lightMarkers = true);
    // How the view draws (light markers, detail, lights left out).
    const Renderer::Options &renderOptions() const { return m_options; }
    // The current values of the program the view draws with (empty before
    // GL starts), read with the context taken back if it is lent.
    UniformSnapshot programSnapshot();
    // The scene's explicit bindings (its "bindings"): the uniforms' new
    // meanings apply from the next frame; vertex inputs keep theirs until
    // the program is linked again.
    void setBindings(const ExplicitBindings &bindings);
    // What each of that program's variables is bound to (core/ShaderBindings.h).
    const ProgramBindings &programBindings() { return m_renderer.program().bindings(); }
    // A white light at the eye that follows the camera: the one light not in
    // world space. A view setting, not part of the scene (currentScene() has
    // no trace of it); added only while fewer than kMaxLights are in use.
    void setHeadlight(bool on);
    bool headlight() const { return m_headlight; }
    // currentScene() plus the headlight: what the renderer draws.
    Scene renderedScene() const;
    // The light whose marker is drawn highlighted (-1: none).
    void setSelectedLight(int index);
    int selectedLight() const { return m_options.selectedLight; }

    void resetCamera();
    void setShowLightMarkers(bool show);
    bool showLightMarkers() const { return m_options.drawLightMarkers; }
    // How the last frame drew each object (level of detail, lights left out).
    const std::vector<Renderer::ObjectDraw> &objectDraws() const
    {
        return m_renderer.objectDraws();
    }
    // What auto detail and, when `leaveOutLights`, leaving out unseen
    // lights may each change a pixel by (linear intensity; Renderer::Options).
    void setModelReduction(double allowance, bool leaveOutLights);

    bool isRenderReady() const { return m_renderReady; }
    // After a frame longer than kHoldFramesAfterMs the view draws nothing
    // until a click, a wheel turn or a key in it, a new program or a new
    // scene (resumeFrames()): such a frame is never repeated by itself.
    bool framesHeld() const { return m_framesHeld; }
    // Frames asked for while held, and not drawn.
    qint64 framesRefused() const { return m_framesRefused; }
    void resumeFrames();
    qint64 framesRendered() const { return m_framesRendered; }
    // The draw times behind frameRendered()'s figure.
    const FrameTimeWindow &frameTimes() const { return m_frameTimes; }
    QString glRendererName() const { return m_glRendererName; }

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

signals:
    // GL could not be set up or the scene could not be drawn; never fatal.
    void renderError(const QString &message);
    // A frame reached the window (after swapBuffers).
    void frameSwapped();
    // After every frame: the draw time (first GL call to glFinish, the
    // window's composition not included), the mean of the frames of the last
    // second (FrameTimeWindow), and the triangles drawn.
    void frameRendered(double milliseconds, qint64 triangles);
    void glRendererChanged(const QString &name);
    void cameraChanged();
    // A new scene (or a new mesh of it) is shown: objects or meshInfo() changed.
    void sceneChanged();
    // Local files were dropped onto the view.
    void filesDropped(const QStringList &paths);
    // GL is up (once, at the first show) and the scene's shipped shading
    // program is in use.
    void glInitialized();
    // The context is about to go: objects shared with it must be let go.
    void glAboutToBeReleased();
    // setScene() put `method`'s shipped program in place of whatever was
    // drawing (the new scene's shading, or the old one's after a failure).
    // Emitted before sceneChanged().
    void shippedProgramLoaded(phonglab::ShadingMethod method);
    // setSceneParameters() or a marker drag changed lights / materials / transforms.
    void sceneParametersChanged();
    // A marker drag ended: one finished move of light `index` (for undo).
    void lightDragged(int index, const phonglab::PointLight &before,
                      const phonglab::PointLight &after);
    // A light marker was clicked.
    void lightPicked(int index);
    // The headlight was switched: the frame changed, the scene did not.
    void headlightChanged(bool on);
    // A frame took `milliseconds` (> kHoldFramesAfterMs): the view now
    // waits for the user before it draws again.
    void framesHeldAfter(double milliseconds);

protected:
    bool event(QEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void childEvent(QChildEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    enum class Drag {
        None,
        Orbit,
        Pan,
        Light
    };

    friend class ViewportWindow;
    // From ViewportWindow: draw and present a frame, unless the context is
    // lent (then once it is back).
    void drawFrame();
    void startGl();
    void initializeGl();
    // Needs the context current: the scene into the window's back buffer
    // (false: GL is not ready, only the background).
    bool drawScene();
    // Books a frame's draw time (first GL call to glFinish) and says so.
    void frameDrawn(double drawMs);
    void framePresented(quint64 loan, double drawMs, qint64 swappedNs, bool ok);
    void drawOverlays();
    QImage readBackBuffer(const QSize &pixels);
    QSize pixelSize() const;
    void cleanup();
    Result<> uploadScene(const Scene &scene, SceneMeshes &&meshes);
    void showUploaded(const Scene &scene);
    bool frameScene();
    QSize windowPixels() const; // the view's native window, in device pixels
    void cameraMoved();
    void sendChangedParameters();
    bool startLightDrag(const QPointF &position);
    void dragLight(const QPointF &position, bool alongView);
    void finishLightDrag();

    Renderer m_renderer;
    Renderer::Options m_options{.drawLightMarkers = true};
    Scene m_scene; // as loaded; its camera is the orbit's original
    // Meshes of m_scene loaded before GL was up; initializeGl uploads them.
    std::optional<SceneMeshes> m_pendingMeshes;
    OrbitCamera m_orbit;
    // The camera is the scene's fitted to the view (frameScene), not moved by
    // the user since: a resize fits it again.
    bool m_cameraFramed = true;
    // The window's size (pixels) when a frame was last swapped on this
    // thread: the back buffer's size, which lags a resize until that swap.
    QSize m_presentedSize;
    bool m_glInitialized = false;  // the renderer holds GL resources
    bool m_renderReady = false;    // ... and a scene and program to draw
    bool m_parametersDirty = true; // camera moved since the renderer last saw it
    Drag m_drag = Drag::None;
    QPointF m_lastMousePos;
    bool m_headlight = false;
    int m_dragLight = -1;         // the light a Drag::Light moves
    PointLight m_dragStart;       // ... as it was when the drag began
    FrameTimeWindow m_frameTimes; // draw times of the last second
    qint64 m_framesRendered = 0;
    QString m_glRendererName;
    ViewportWindow *m_window = nullptr; // owned by m_container
    QWidget *m_container = nullptr;
    // Made on the first exposure; stays (invalid) when it could not be made.
    std::unique_ptr<QOpenGLContext> m_context;
    ContextLender m_lender;
    // Presents the first frame of a newly adopted program off the GUI
    // thread, so that the keys typed meanwhile are handled at once; null:
    // this thread presents (PHONGLAB_PRESENT_ON_GUI_THREAD=1, or the
    // platform cannot). Other frames (an orbit's stream) are presented here:
    // handing the context over costs ~3 ms a frame (docs/performance.md).
    std::unique_ptr<FramePresenter> m_presenter;
    bool m_mayPresentOffThread = true;
    bool m_presentOffThread = false;
    quint64 m_presentLoans = 0; // the newest loan to the presenter: only it ends one
    std::chrono::steady_clock::time_point m_lastPresentedAt;
    bool m_frameMissed = false;      // asked for while the context was lent
    WarmUpDraw m_warmer;             // created in this context by a borrower; freed in cleanup()
    GLint m_framebufferSamples = -1; // of the window's framebuffer; -1: not known yet
    // The child widgets drawn over the frame, as last painted.
    ImageLayer m_overlayLayer;
    QImage m_overlayImage;
    bool m_overlayDirty = true;
    bool m_paintingOverlays = false; // their paint events are ours, not changes
    bool m_framesHeld = false;       // a frame ran long: none until the user acts
    qint64 m_framesRefused = 0;
};

} // namespace phonglab
