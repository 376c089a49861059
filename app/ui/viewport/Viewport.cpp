// Viewport: the scene shown, its GL context's life and loans (its input is
// in ViewportInput.cpp, its frames in ViewportFrames.cpp).
#include "Viewport.h"

#include "CurrentContext.h"
#include "FramePresenter.h"
#include "ViewportWindow.h"
#include "core/CameraFraming.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QResizeEvent>
#include <algorithm>

namespace phonglab {

namespace {

constexpr int kGiveBackTimeoutMs =
    5000; // a borrower stuck in the driver (a shader that never ends)

QString contextDescription(QOpenGLContext *context)
{
    QOpenGLFunctions *f = context->functions();
    const auto text = [f](GLenum name) {
        return QString::fromLatin1(reinterpret_cast<const char *>(f->glGetString(name)));
    };
    return QStringLiteral("OpenGL %1 (%2)").arg(text(GL_VERSION), text(GL_RENDERER));
}

} // namespace

Viewport::Viewport(QWidget *parent, bool presentOffThread)
    : QWidget(parent)
    , m_window(new ViewportWindow(this))
    , m_mayPresentOffThread(presentOffThread)
{
    setFocusPolicy(Qt::StrongFocus); // so R / Home reach keyPressEvent after a click
    setAcceptDrops(true);
    m_container = QWidget::createWindowContainer(m_window, this);
    // Events made for this widget (tests, drops found by position) reach it,
    // not the container; the window's own input is passed on by ViewportWindow.
    m_container->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_container->setFocusPolicy(Qt::NoFocus);
}

Viewport::~Viewport()
{
    cleanup();
    if (m_lender.isActive()) {
        // A borrower stuck in the driver: its context is left, as said, and
        // a stuck presenter's thread too (waiting for it would never end).
        if (m_presenter && m_lender.borrower() == m_presenter->presenterThread())
            (void)m_presenter.release();
        (void)m_context.release();
    }
}

void Viewport::makeCurrent()
{
    if (m_context && m_context->isValid())
        m_context->makeCurrent(m_window);
}

void Viewport::doneCurrent()
{
    if (m_context && QOpenGLContext::currentContext() == m_context.get())
        m_context->doneCurrent();
}

void Viewport::setFormat(const QSurfaceFormat &format)
{
    m_window->setFormat(format);
}

QSurfaceFormat Viewport::format() const
{
    return m_context && m_context->isValid() ? m_context->format() : m_window->requestedFormat();
}

void Viewport::requestFrame()
{
    m_window->requestFrame();
}

QWindow *Viewport::frameWindow() const
{
    return m_window;
}

QSize Viewport::pixelSize() const
{
    return size() * devicePixelRatioF();
}

QSize Viewport::minimumSizeHint() const
{
    return {200, 150};
}

QSize Viewport::sizeHint() const
{
    return {960, 720};
}

Result<> Viewport::setScene(const Scene &scene)
{
    return setScene(scene, loadSceneMeshes(scene, loadedKeys()));
}

Result<> Viewport::setScene(const Scene &scene, SceneMeshes &&meshes)
{
    if (!meshes.ok())
        return fail(meshes.error);
    if (m_glInitialized) {
        Result<> uploaded;
        bool programReplaced = false;
        {
            const CurrentContext current(*this);
            const GLuint programBefore = m_renderer.program().id();
            uploaded = uploadScene(scene, std::move(meshes));
            programReplaced = m_renderer.program().id() != programBefore;
        }
        if (programReplaced) // the new scene's shading, or the old one restored after a failure
            emit shippedProgramLoaded(uploaded ? scene.shading : m_scene.shading);
        if (!uploaded)
            return uploaded;
        m_renderReady = true;
    } else {
        // A scene accepted here must not fail later in the GL start (initializeGl), so check
        // now that nothing is missing.
        for (const SceneObject &object : scene.objects) {
            if (!meshes.entries.contains(meshKey(scene, object)))
                return fail(tr("%1: mesh was not loaded").arg(scene.resolveMeshPath(object.mesh)));
        }
        m_pendingMeshes = std::move(meshes);
    }
    showUploaded(scene);
    return {};
}

QSet<QString> Viewport::loadedKeys() const
{
    // Pending meshes are not counted: a new pending set replaces them.
    return m_glInitialized ? m_renderer.loadedKeys() : QSet<QString>();
}

const QHash<QString, SceneMeshes::Entry> &Viewport::meshInfo() const
{
    static const QHash<QString, SceneMeshes::Entry> none;
    if (m_glInitialized)
        return m_renderer.meshInfo();
    return m_pendingMeshes ? m_pendingMeshes->entries : none;
}

void Viewport::showUploaded(const Scene &scene)
{
    m_scene = scene;
    m_framesHeld = false; // a new scene is drawn once at least
    frameScene();
    cameraMoved();
    emit sceneChanged();
}

// The scene's camera, moved back as far as this view's shape needs to show
// every object (framedCamera); the orbit starts there and Reset returns
// there. True when that moved the camera.
bool Viewport::frameScene()
{
    const QSize pixels = pixelSize();
    const double aspect = pixels.isEmpty() ? 0.0 : double(pixels.width()) / pixels.height();
    const Camera framed = m_scene.camera.frameObjects
        ? framedCamera(m_scene.camera, objectBoundsCorners(m_scene, meshInfo()), aspect)
        : m_scene.camera;
    m_cameraFramed = true;
    if (framed == m_orbit.original() && framed == m_orbit.camera())
        return false;
    m_orbit.setOriginal(framed);
    return true;
}

Camera Viewport::cameraToSave() const
{
    return m_cameraFramed ? m_scene.camera : currentScene().camera;
}

Scene Viewport::currentScene() const
{
    Scene scene = m_scene;
    scene.camera = m_orbit.camera();
    // Moved by the user: a composed shot, to be shown as it is.
    scene.camera.frameObjects = m_scene.camera.frameObjects && m_cameraFramed;
    return scene;
}

void Viewport::setShading(ShadingMethod method)
{
    m_scene.shading = method;
    // The renderer's copy decides whether a later scene must reload its
    // program, so it has to follow now rather than at the next paint.
    if (m_renderReady)
        m_renderer.updateSceneParameters(renderedScene());
    cameraMoved(); // the parameters changed; repaint
}

void Viewport::adoptProgram(GlProgram program)
{
    if (!m_glInitialized)
        return; // no context to free it with either; it goes with its share group
    {
        const CurrentContext current(*this);
        m_renderer.adoptProgram(std::move(program));
    }
    m_presentOffThread = true; // the frame after an edit: typing goes on meanwhile
    m_framesHeld = false;      // a new program is drawn once at least
    requestFrame();
}

BuiltProgram Viewport::buildProgram(const ShaderSource &vertex, const ShaderSource &fragment)
{
    BuiltProgram built;
    if (!m_glInitialized) {
        built.report.diagnostics.push_back({BuildStep::Link,
                                            ShaderDiagnostic::Severity::Error,
                                            {},
                                            0,
                                            0,
                                            tr("OpenGL is not running in the viewport")});
        return built;
    }
    const CurrentContext current(*this);
    return ProgramBuilder().build(vertex, fragment, {}, m_scene.bindings);
}

std::optional<LentContext> Viewport::lendContext(QThread *borrower)
{
    // A frame being presented is waited for first (a frame's time).
    if (!m_glInitialized || !takeBackContext())
        return std::nullopt;
    // A loan is for a new program's warm-up (the borrower may switch the
    // renderer to it): the frame after it is an edit's.
    m_presentOffThread = true;
    // The warm-up draws into the window's own framebuffer only where a
    // context may be current on a window off the GUI thread.
    QSurface *surface = QOpenGLContext::supportsThreadedOpenGL() ? m_window : nullptr;
    return m_lender.lend(m_context.get(), surface, borrower, &m_warmer,
                         std::max(0, m_framebufferSamples));
}

bool Viewport::takeBackContext(int timeoutMs)
{
    QThread *borrower = m_lender.borrower();
    if (!m_lender.end(timeoutMs))
        return false;
    // Back from a warm-up, whose borrower may have switched the renderer to
    // the new program: its frame is due, as is any asked for meanwhile.
    const bool fromWarmUp =
        borrower && (!m_presenter || borrower != m_presenter->presenterThread());
    if (m_frameMissed || fromWarmUp) {
        m_frameMissed = false;
        requestFrame();
    }
    return true;
}

// The frame window covers this widget, so the cursor shown over the view
// is that window's.
bool Viewport::event(QEvent *event)
{
    if (event->type() == QEvent::CursorChange)
        m_window->setCursor(cursor());
    return QWidget::event(event);
}

void Viewport::resizeEvent(QResizeEvent *event)
{
    m_container->setGeometry(rect());
    // Until the user moves the camera, it keeps every object in view.
    if (m_cameraFramed && frameScene())
        cameraMoved();
    requestFrame(); // not every platform exposes a resized window again
    QWidget::resizeEvent(event);
}

void Viewport::setSceneParameters(const Scene &scene)
{
    m_scene.ambient = scene.ambient;
    m_scene.lights = scene.lights;
    const size_t count = std::min(m_scene.objects.size(), scene.objects.size());
    for (size_t i = 0; i < count; ++i) {
        m_scene.objects[i].material = scene.objects[i].material;
        m_scene.objects[i].transform = scene.objects[i].transform;
    }
    if (m_options.selectedLight >= int(m_scene.lights.size()))
        setSelectedLight(int(m_scene.lights.size()) - 1);
    m_parametersDirty = true;
    requestFrame();
    emit sceneParametersChanged();
}

void Viewport::setBindings(const ExplicitBindings &bindings)
{
    m_scene.bindings = bindings;
    m_parametersDirty = true;
    requestFrame();
    emit sceneParametersChanged();
}

UniformSnapshot Viewport::programSnapshot()
{
    if (!m_renderReady)
        return {};
    const CurrentContext current(*this);
    return m_renderer.program().snapshot();
}

void Viewport::setHeadlight(bool on)
{
    m_headlight = on;
    m_parametersDirty = true;
    requestFrame();
    emit headlightChanged(on);
}

Scene Viewport::renderedScene() const
{
    Scene scene = currentScene();
    // Disabled lights are not sent to the shader, so they leave room for it.
    const auto enabledLights = std::count_if(scene.lights.begin(), scene.lights.end(),
                                             [](const PointLight &l) { return l.enabled; });
    if (m_headlight && enabledLights < kMaxLights) {
        PointLight head;
        head.position = scene.camera.eye; // moves with every orbit, pan and zoom
        scene.lights.push_back(head);
    }
    return scene;
}

void Viewport::setSelectedLight(int index)
{
    m_options.selectedLight = index;
    m_renderer.setOptions(m_options); // plain state, no GL call
    requestFrame();
}

void Viewport::resetCamera()
{
    m_orbit.reset();
    frameScene();
    cameraMoved();
}

void Viewport::setModelReduction(double allowance, bool leaveOutLights)
{
    m_options.lightAllowance = leaveOutLights ? allowance : 0.0;
    m_options.detailShadingAllowance = allowance;
    m_renderer.setOptions(m_options); // plain state, no GL call
    requestFrame();
}

void Viewport::setShowLightMarkers(bool show)
{
    m_options.drawLightMarkers = show;
    m_renderer.setOptions(m_options); // plain state, no GL call
    requestFrame();
}

void Viewport::initializeGl()
{
    m_glRendererName = contextDescription(context());
    emit glRendererChanged(m_glRendererName);

    if (const Result<> initialized = m_renderer.initialize(); !initialized) {
        emit renderError(
            tr("Cannot render with %1: %2").arg(m_glRendererName, initialized.error()));
        return;
    }
    m_renderer.setOptions(m_options);
    m_glInitialized = true;
    // Pending meshes are there after the first show; after a context change
    // (the widget moved to another window) the scene is loaded again here.
    SceneMeshes meshes = m_pendingMeshes ? std::move(*m_pendingMeshes) : loadSceneMeshes(m_scene);
    m_pendingMeshes.reset();
    if (const Result<> uploaded = uploadScene(currentScene(), std::move(meshes)); !uploaded) {
        emit renderError(uploaded.error());
        return;
    }
    m_parametersDirty = false;
    m_renderReady = true;
    emit sceneChanged(); // meshInfo() now comes from the renderer
    emit glInitialized();
}

// Needs the context current. The shading program goes first because it is the
// cheap one to restore if the meshes then fail.
Result<> Viewport::uploadScene(const Scene &scene, SceneMeshes &&meshes)
{
    const ShadingMethod previousShading = m_renderer.scene().shading;
    const bool reloadShading = !m_renderer.hasProgram() || scene.shading != previousShading;
    if (reloadShading) {
        const BuildReport built = m_renderer.loadShading(scene.shading);
        if (!built.ok) // the renderer keeps its previous program
            return fail(tr("Cannot build the %1 shading program:\n%2")
                            .arg(shadingName(scene.shading), built.errorSummary()));
    }
    Result<> set = m_renderer.setScene(scene, std::move(meshes));
    if (!set && reloadShading && scene.shading != previousShading)
        m_renderer.loadShading(previousShading);
    return set;
}

void Viewport::cleanup()
{
    if (m_glInitialized) {
        emit glAboutToBeReleased(); // the borrower stops, and gives the context back
        if (takeBackContext(kGiveBackTimeoutMs)) {
            makeCurrent();
            m_warmer.destroy();
            m_overlayLayer.destroy();
            m_renderer.cleanup();
            doneCurrent();
        } else {
            qWarning("phonglab: the viewport's OpenGL context was not given back; its resources "
                     "are left");
        }
    }
    m_glInitialized = false;
    m_renderReady = false;
}

// Needs the context current: camera, lights and materials changed since the
// last frame go to the renderer once, just before a frame is drawn.
void Viewport::sendChangedParameters()
{
    if (!m_parametersDirty)
        return;
    m_renderer.updateSceneParameters(renderedScene());
    m_parametersDirty = false;
}

void Viewport::cameraMoved()
{
    m_parametersDirty = true;
    requestFrame();
    emit cameraChanged();
}

} // namespace phonglab
