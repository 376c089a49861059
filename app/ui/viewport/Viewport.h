#pragma once
#include "ViewContext.h"
#include "ViewDrawing.h"
#include "ViewFrames.h"
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
// The view is three rooms behind this face: ViewportSurface (the window,
// the context, its loans, presenting and timing frames), ViewportInput
// (mouse, keys, drops) and GpuScene (the scene, camera and renderer), with
// WidgetOverlay drawing the children. This class ties them together and is
// what the rest of the window talks to: the scene and its camera here, the
// rest through narrow faces (ViewProgram, ViewDrawing, ViewFrames,
// ViewContext), so that nothing outside the view reaches its renderer.
class Viewport : public QWidget,
                 private ViewportSurface::Content,
                 private ViewDrawing,
                 private ViewContext
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

    // currentScene() plus the headlight: what the renderer draws.
    Scene renderedScene() const;
    void resetCamera();
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
    // A frame drawn now (overlays included) and read back, once a lent
    // context is back; null before the window was first shown.
    QImage grabFramebuffer();
    bool isRenderReady() const { return m_gpu.isReady(); }

    // The view's narrow faces, each for what its users need of it:
    // the program it draws with (its uniforms, bindings, a new one adopted),
    ViewProgram &program() { return m_program; }
    // how it draws beside the scene (markers, headlight, detail),
    ViewDrawing &drawing() { return *this; }
    // its frames (asking for one, their times and counts),
    ViewFrames &frames() { return *m_surface; }
    // and its GL context as another thread borrows it.
    ViewContext &glContext() { return *this; }

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
    // A new program, the bindings and the method change the frame and its hold.
    friend class ViewProgram;

    // ViewDrawing
    const Renderer::Options &renderOptions() const override { return m_gpu.options(); }
    void setShowLightMarkers(bool show) override;
    bool showLightMarkers() const override { return m_gpu.options().drawLightMarkers; }
    void setSelectedLight(int index) override;
    void setHeadlight(bool on) override;
    void setReductionAllowance(double allowance, bool leaveOutLights) override;
    const std::vector<Renderer::ObjectDraw> &objectDraws() const override
    {
        return m_gpu.renderer().objectDraws();
    }
    const DepthRange &depthRange() const override { return m_gpu.renderer().depthRange(); }
    // ViewContext
    std::optional<LentContext> lendContext(QThread *borrower) override;
    LentRenderer lentRenderer() override { return LentRenderer(&m_gpu.renderer()); }
    bool takeBackContext(int timeoutMs) override;
    bool isContextLent() const override { return m_surface->isContextLent(); }
    QOpenGLContext *context() const override { return m_surface->context(); }
    QString glRendererName() const override { return m_glRendererName; }

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
    void requestFrame() { m_surface->requestFrame(); }
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
