#pragma once
#include "LentRenderer.h"
#include "ViewProgram.h"
#include "ViewportSurface.h"
#include "render/draw/GpuScene.h"
#include "render/gl/LentContext.h"
#include "render/gl/SharedGlObject.h"

#include <QImage>
#include <QOpenGLContext>
#include <QWidget>
#include <chrono>
#include <optional>

namespace phonglab {

class ViewportInput;
class WidgetOverlay;

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
//
// The view is three rooms behind this one face: ViewportSurface (the window,
// the context, its loans, presenting and timing frames), ViewportInput
// (mouse, keys, drops) and GpuScene (the scene, camera and renderer), with
// WidgetOverlay drawing the children. This class ties them together and is
// what the rest of the window talks to; the renderer itself it keeps: the
// window reaches the program it draws with through ViewProgram, and a
// borrower of its context through LentRenderer.
class Viewport : public QWidget, private ViewportSurface::Content
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
    const Camera &camera() const { return m_gpu.camera(); }
    // What Save writes: the scene's own camera until the user moves it (a
    // camera moved back only to fit this view's shape is not the scene's),
    // the moved one after, marked as a shot to keep (frameObjects false).
    Camera cameraToSave() const;

    // The scene's shading method changes without touching the program: the
    // live shader controller builds it (so Save writes the method in use).
    void setShading(ShadingMethod method);

    // Switches to a program linked on a context sharing this one's objects
    // (the build thread's) and owns it from then on; uniforms the user set
    // carry over. Needs GL to be up (glInitialized()).
    void adoptProgram(GlProgram program);
    // The program the view draws with: its uniforms, its bindings.
    ViewProgram &program() { return m_program; }
    // The near/far planes of the last frame (no GL call; any time).
    const DepthRange &depthRange() const { return m_gpu.renderer().depthRange(); }

    // Lends the GL context to `borrower` (see LentContext), so that a new
    // program's draw-time compile happens in this very context but off the
    // GUI thread. Until takeBackContext() the view does not paint, and anything that
    // needs the context on this thread first waits for it to come back.
    // Waits for a frame being presented first. Refused (nullopt) before GL
    // is up: the caller then does the work itself.
    std::optional<LentContext> lendContext(QThread *borrower);
    // The renderer as the borrower may use it while the loan lasts.
    LentRenderer lentRenderer() { return LentRenderer(&m_gpu.renderer()); }
    // Waits for a lent context (at most timeoutMs; -1: as long as it takes)
    // and paints again. False if it did not come back in time.
    bool takeBackContext(int timeoutMs = -1);
    bool isContextLent() const { return m_surface->isContextLent(); }
    // Samples of the framebuffer the view draws into (-1 before the first frame).
    int framebufferSamples() const { return m_surface->framebufferSamples(); }
    // A frame drawn now (overlays included) and read back, once a lent
    // context is back; null before the window was first shown.
    QImage grabFramebuffer();

    // The view's GL context (null before the window was first shown), made
    // current on this thread by CurrentContext only.
    QOpenGLContext *context() const { return m_surface->context(); }
    // The format the view's window asks for (samples, depth); set before the
    // window is first shown.
    void setFormat(const QSurfaceFormat &format);
    // A new frame at the next turn of the event loop (QWidget::update()
    // repaints only the widget around the view's window).
    void requestFrame();
    // A frame is on its way (frameRendered will come) without asking for one.
    bool isFrameComing() const { return m_surface->isFrameComing(); }
    // The native window the frames go to; its input reaches this widget.
    QWindow *frameWindow() const;
    // When the last frame was handed to the window system (swapBuffers
    // returned), on whichever thread presented it.
    std::chrono::steady_clock::time_point lastPresentedAt() const
    {
        return m_surface->lastPresentedAt();
    }

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
    const Renderer::Options &renderOptions() const { return m_gpu.options(); }
    // The scene's explicit bindings (its "bindings"): the uniforms' new
    // meanings apply from the next frame; vertex inputs keep theirs until
    // the program is linked again.
    void setBindings(const ExplicitBindings &bindings);
    // A white light at the eye that follows the camera: the one light not in
    // world space. A view setting, not part of the scene (currentScene() has
    // no trace of it); added only while fewer than kMaxLights are in use.
    void setHeadlight(bool on);
    // currentScene() plus the headlight: what the renderer draws.
    Scene renderedScene() const;
    // The light whose marker is drawn highlighted (-1: none).
    void setSelectedLight(int index);

    void resetCamera();
    void setShowLightMarkers(bool show);
    bool showLightMarkers() const { return m_gpu.options().drawLightMarkers; }
    // How the last frame drew each object (level of detail, lights left out).
    const std::vector<Renderer::ObjectDraw> &objectDraws() const
    {
        return m_gpu.renderer().objectDraws();
    }
    // What auto detail and, when `leaveOutLights`, leaving out unseen
    // lights may each change a pixel by (linear intensity; Renderer::Options).
    void setReductionAllowance(double allowance, bool leaveOutLights);

    bool isRenderReady() const { return m_gpu.isReady(); }
    FrameStats frameStats() const { return m_surface->frameStats(); }
    // The draw times behind frameRendered()'s figure.
    const FrameTimeWindow &frameTimes() const { return m_surface->frameTimes(); }
    QString glRendererName() const { return m_glRendererName; }

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

signals:
    // GL could not be set up or the scene could not be drawn; never fatal.
    void renderError(const QString &message);
    // A frame reached the window (after swapBuffers).
    void frameSwapped();
    // After every frame: the mean draw time of the last second's frames
    // (FrameTimeWindow; first GL call to glFinish, the window's composition
    // not included), not this frame's own, and the triangles drawn.
    void frameRendered(double meanMsOfLastSecond, qint64 triangles);
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

private:
    friend class CurrentContext; // the one way to make the context current

    // As QOpenGLWidget's: CurrentContext's, and the view's own.
    void makeCurrent();
    void doneCurrent();
    // ViewportSurface::Content
    bool drawScene(const QSize &pixels) override;
    void drawOverlays(const QSize &pixels) override;
    std::function<void(const QSize &)> drawForBorrower(const QSize &pixels) override;

    void initializeGl();
    void cleanup();
    void resumeFrames();
    int selectedLight() const { return m_gpu.options().selectedLight; }
    QSize pixelSize() const;
    void showUploaded(const Scene &scene);
    // The camera or another parameter changed: a new frame.
    void parametersChanged();
    void cameraMoved();

    GpuScene m_gpu;
    ViewProgram m_program{this, &m_gpu};
    ViewportSurface *m_surface = nullptr; // children of this widget
    ViewportInput *m_input = nullptr;
    WidgetOverlay *m_overlay = nullptr;
    QString m_glRendererName;
};

} // namespace phonglab
