#include "Viewport.h"

#include "CurrentContext.h"

#include "FramePresenter.h"
#include "LightPicking.h"
#include "ViewportWindow.h"
#include "render/FramebufferImage.h"

#include <QAction>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMimeData>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QResizeEvent>
#include <QWheelEvent>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace phonglab {

namespace {

constexpr double kOrbitDegPerPixel = 0.4;
constexpr double kZoomPerWheelNotch = 0.85; // distance factor for one notch towards the scene
constexpr double kWheelNotch = 120.0;       // QWheelEvent::angleDelta() units per notch
constexpr int kGiveBackTimeoutMs =
    5000; // a borrower stuck in the driver (a shader that never ends)
constexpr double kLightPickRadiusPx = 8.0; // how near a click must be to a marker

double msSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// The local files among dropped URLs; anything else (web links) is not ours.
QStringList localFiles(const QMimeData *data)
{
    QStringList paths;
    if (!data || !data->hasUrls())
        return paths;
    for (const QUrl &url : data->urls())
        if (url.isLocalFile())
            paths << url.toLocalFile();
    return paths;
}

QString contextDescription(QOpenGLContext *context)
{
    QOpenGLFunctions *f = context->functions();
    const auto text = [f](GLenum name) {
        return QString::fromLatin1(reinterpret_cast<const char *>(f->glGetString(name)));
    };
    return QStringLiteral("OpenGL %1 (%2)").arg(text(GL_VERSION), text(GL_RENDERER));
}

} // namespace

Viewport::Viewport(QWidget *parent)
    : QWidget(parent)
    , m_window(new ViewportWindow(this))
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
    if (m_lender.isActive())
        (void)m_context.release(); // still with a borrower stuck in the driver: left, as said
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
        // A scene accepted here must not fail later in initializeGL, so check
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
    m_orbit.setOriginal(scene.camera);
    cameraMoved();
    emit sceneChanged();
}

Scene Viewport::currentScene() const
{
    Scene scene = m_scene;
    scene.camera = m_orbit.camera();
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
    requestFrame();
}

BuiltProgram Viewport::buildProgram(const ShaderSource &vertex, const ShaderSource &fragment)
{
    BuiltProgram built;
    if (!m_glInitialized) {
        built.result.diagnostics.push_back({BuildStep::Link,
                                            ShaderDiagnostic::Severity::Error,
                                            {},
                                            0,
                                            0,
                                            tr("OpenGL is not running in the viewport")});
        return built;
    }
    const CurrentContext current(*this);
    return ProgramBuilder().build(vertex, fragment);
}

std::optional<LentContext> Viewport::lendContext(QThread *borrower)
{
    if (!m_glInitialized || !takeBackContext()) // a frame being presented first
        return std::nullopt;
    // A loan is for a new program's warm-up (the borrower may switch the
    // renderer to it): the frame after it is an edit's.
    m_presentOffThread = true;
    return m_lender.lend(m_context.get(), m_window, borrower, &m_warmer,
                         std::max(0, m_framebufferSamples));
}

bool Viewport::takeBackContext(int timeoutMs)
{
    if (!m_lender.end(timeoutMs))
        return false;
    if (m_frameMissed) {
        m_frameMissed = false;
        requestFrame();
    }
    return true;
}

QImage Viewport::grabFramebuffer()
{
    takeBackContext();
    if (!m_context || !m_context->isValid() || !m_window->handle())
        return {};
    makeCurrent();
    const auto started = std::chrono::steady_clock::now();
    if (drawScene()) {
        m_context->functions()->glFinish(); // without it the time would be the submission's
        frameDrawn(msSince(started));
    }
    drawOverlays();
    QImage image = readBackBuffer(pixelSize()).convertToFormat(QImage::Format_RGB32);
    doneCurrent();
    image.setDevicePixelRatio(devicePixelRatioF());
    return image;
}

// Needs the context current: the bottom-left `pixels` of the window's back
// buffer, resolved by the read, top row first.
QImage Viewport::readBackBuffer(const QSize &pixels)
{
    QImage image(pixels, QImage::Format_RGBA8888);
    QOpenGLExtraFunctions *f = m_context->extraFunctions();
    f->glBindFramebuffer(GL_READ_FRAMEBUFFER, m_context->defaultFramebufferObject());
    f->glReadBuffer(GL_BACK);
    f->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    f->glReadPixels(0, 0, pixels.width(), pixels.height(), GL_RGBA, GL_UNSIGNED_BYTE, image.bits());
    return image.mirrored();
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
    QWidget::resizeEvent(event);
}

// Every child widget but the window's container lies over the frame and is
// drawn into it: a change to one is a new frame.
void Viewport::childEvent(QChildEvent *event)
{
    if (event->added() && event->child()->isWidgetType())
        event->child()->installEventFilter(this);
    QWidget::childEvent(event);
}

bool Viewport::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_container)
        return false;
    switch (event->type()) {
    case QEvent::Paint:
        if (m_paintingOverlays)
            break;
        [[fallthrough]];
    case QEvent::Show:
    case QEvent::Hide:
    case QEvent::Move:
    case QEvent::Resize:
        m_overlayDirty = true;
        requestFrame();
        break;
    default: break;
    }
    return false;
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

UniformSnapshot Viewport::programSnapshot()
{
    if (!m_renderReady)
        return {};
    const CurrentContext current(*this);
    return m_renderer.program().snapshot();
}

QImage Viewport::renderImage(const QSize &pixelSize, bool lightMarkers)
{
    if (!m_renderReady || pixelSize.isEmpty())
        return {};
    const CurrentContext current(*this);
    sendChangedParameters();
    Renderer::Options options = m_options;
    options.drawLightMarkers = options.drawLightMarkers && lightMarkers;
    m_renderer.setOptions(options);
    // Up to the window's size (the live check): drawn into a corner of the
    // window's back buffer, the framebuffer whose shader variant the lent
    // warm-up compiled off the GUI thread; any other framebuffer would cost
    // llvmpipe another compile here, ~80 ms after every edit. Larger (an
    // export): a framebuffer object with the view's samples.
    const QSize window = this->pixelSize();
    const bool inWindow =
        pixelSize.width() <= window.width() && pixelSize.height() <= window.height();
    QImage image;
    if (inWindow) {
        m_context->functions()->glBindFramebuffer(GL_FRAMEBUFFER,
                                                  m_context->defaultFramebufferObject());
        m_renderer.render(pixelSize);
        // What is on screen stays: every frame redraws the whole back buffer
        // before it swaps.
        image = readBackBuffer(pixelSize).convertToFormat(QImage::Format_RGB32);
    } else {
        image = drawIntoImage(m_renderer, pixelSize, m_framebufferSamples);
    }
    m_renderer.setOptions(m_options);
    return image;
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

bool Viewport::startLightDrag(const QPointF &position)
{
    if (!m_options.drawLightMarkers)
        return false; // nothing visible to grab
    m_dragLight =
        pickLight(m_scene.lights, m_orbit.camera(), QSizeF(size()), position, kLightPickRadiusPx);
    if (m_dragLight < 0)
        return false;
    m_dragStart = m_scene.lights[m_dragLight];
    setSelectedLight(m_dragLight);
    emit lightPicked(m_dragLight);
    return true;
}

void Viewport::dragLight(const QPointF &position, bool alongView)
{
    glm::dvec3 &p = m_scene.lights[m_dragLight].position;
    p = alongView
        ? moveAlongView(p, m_orbit.camera(), QSizeF(size()), position.y() - m_lastMousePos.y())
        : moveInViewPlane(p, m_orbit.camera(), QSizeF(size()), position);
    m_parametersDirty = true;
    requestFrame();
    emit sceneParametersChanged();
}

void Viewport::finishLightDrag()
{
    const int index = m_dragLight;
    m_dragLight = -1;
    if (index >= 0 && index < int(m_scene.lights.size()) && !(m_scene.lights[index] == m_dragStart))
        emit lightDragged(index, m_dragStart, m_scene.lights[index]);
}

void Viewport::resetCamera()
{
    m_orbit.reset();
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

void Viewport::drawFrame()
{
    if (m_lender.isActive()) {
        m_frameMissed = true;
        return;
    }
    if (!m_window->isExposed())
        return;
    if (!m_context)
        startGl();
    if (!m_context->isValid() || !m_context->makeCurrent(m_window))
        return;
    const auto started = std::chrono::steady_clock::now();
    const bool scene = drawScene();
    drawOverlays();
    if (scene && m_presenter && std::exchange(m_presentOffThread, false)) {
        // The wait for the rasteriser and the swap go to the presenter's
        // thread; this one goes back to its events (typing) meanwhile.
        std::optional<LentContext> lent =
            m_lender.lend(m_context.get(), m_window, m_presenter->presenterThread(), nullptr,
                          std::max(0, m_framebufferSamples));
        m_presenter->present(std::move(*lent), thread(), started);
        return;
    }
    if (scene) {
        m_context->functions()->glFinish(); // without it the time would be the submission's
        frameDrawn(msSince(started));
    }
    m_context->swapBuffers(m_window);
    m_lastPresentedAt = std::chrono::steady_clock::now();
    emit frameSwapped();
}

void Viewport::framePresented(double drawMs, qint64 swappedNs, bool ok)
{
    takeBackContext(); // given back already: the presenter releases it first
    if (!ok) {
        // The context cannot be made current off this thread here: present
        // on this thread from now on.
        qWarning("phonglab: frames cannot be presented from a thread of their own; the GUI "
                 "thread presents them");
        m_presenter.reset();
        requestFrame();
        return;
    }
    m_lastPresentedAt =
        std::chrono::steady_clock::time_point(std::chrono::steady_clock::duration(swappedNs));
    frameDrawn(drawMs);
    emit frameSwapped();
}

// Once, on the first exposure: the context for the window's format, sharing
// objects with the rest of the application (the build thread's context).
void Viewport::startGl()
{
    m_context = std::make_unique<QOpenGLContext>();
    m_context->setFormat(m_window->requestedFormat());
    m_context->setShareContext(QOpenGLContext::globalShareContext());
    if (!m_context->create() || !m_context->makeCurrent(m_window)) {
        emit renderError(tr("Cannot create an OpenGL context for the viewport"));
        m_context = std::make_unique<QOpenGLContext>(); // invalid: no second try
        return;
    }
    if (!qEnvironmentVariableIsSet("PHONGLAB_PRESENT_ON_GUI_THREAD")) {
        m_presenter = std::make_unique<FramePresenter>();
        connect(m_presenter.get(), &FramePresenter::presented, this, &Viewport::framePresented,
                Qt::QueuedConnection);
    }
    initializeGl();
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

// Needs the context current: the scene into the window's back buffer.
bool Viewport::drawScene()
{
    QOpenGLFunctions *f = context()->functions();
    f->glBindFramebuffer(GL_FRAMEBUFFER, m_context->defaultFramebufferObject());
    if (!m_renderReady) {
        // Nothing to draw (GL failed and was reported): show the background.
        const glm::dvec3 bg = m_scene.background;
        f->glClearColor(float(bg.r), float(bg.g), float(bg.b), 1.0f);
        f->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return false;
    }
    sendChangedParameters();
    if (m_framebufferSamples < 0) {
        // What the window really got, not what was asked for: a warm-up
        // must draw with the same.
        f->glGetIntegerv(GL_SAMPLES, &m_framebufferSamples);
    }
    m_renderer.render(pixelSize());
    return true;
}

void Viewport::frameDrawn(double drawMs)
{
    const auto now = std::chrono::steady_clock::now().time_since_epoch();
    m_frameTimes.add(std::chrono::duration_cast<std::chrono::nanoseconds>(now).count(), drawMs);
    ++m_framesRendered;
    emit frameRendered(m_frameTimes.meanMs(), m_renderer.trianglesDrawn());
}

// Needs the context current: the visible child widgets over the frame, as
// QPainter draws them (premultiplied), painted again only when one changed.
void Viewport::drawOverlays()
{
    QList<QWidget *> shown;
    for (QWidget *child : findChildren<QWidget *>(Qt::FindDirectChildrenOnly))
        if (child != m_container && child->isVisible())
            shown << child;
    if (shown.isEmpty())
        return;
    const QSize pixels = pixelSize();
    if (m_overlayDirty || m_overlayImage.size() != pixels) {
        QImage image(pixels, QImage::Format_RGBA8888_Premultiplied);
        image.setDevicePixelRatio(devicePixelRatioF());
        image.fill(Qt::transparent);
        m_paintingOverlays = true;
        {
            QPainter painter(&image);
            for (QWidget *child : shown)
                child->render(&painter, child->pos(), QRegion(), QWidget::DrawChildren);
        }
        m_paintingOverlays = false;
        m_overlayImage = image;
        m_overlayDirty = false;
    }
    m_overlayLayer.draw(m_overlayImage, pixels);
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

void Viewport::mousePressEvent(QMouseEvent *event)
{
    switch (event->button()) {
    case Qt::LeftButton:
        m_drag = startLightDrag(event->position()) ? Drag::Light : Drag::Orbit;
        break;
    case Qt::RightButton:
    case Qt::MiddleButton: m_drag = Drag::Pan; break;
    default: QWidget::mousePressEvent(event); return;
    }
    m_lastMousePos = event->position();
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent *event)
{
    if (m_drag == Drag::None) {
        QWidget::mouseMoveEvent(event);
        return;
    }
    if (m_drag == Drag::Light) {
        dragLight(event->position(), event->modifiers() & Qt::ShiftModifier);
        m_lastMousePos = event->position();
        event->accept();
        return;
    }
    const QPointF delta = event->position() - m_lastMousePos;
    m_lastMousePos = event->position();
    if (m_drag == Drag::Orbit) {
        // "Grab the object" feel: dragging right turns its front to the right.
        m_orbit.orbit(-delta.x() * kOrbitDegPerPixel, delta.y() * kOrbitDegPerPixel);
    } else {
        const double viewHeight = std::max(1, height());
        m_orbit.pan(delta.x() / viewHeight, delta.y() / viewHeight);
    }
    cameraMoved();
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->buttons() == Qt::NoButton) {
        if (m_drag == Drag::Light)
            finishLightDrag(); // the whole drag is one undo step
        m_drag = Drag::None;
    }
    event->accept();
}

void Viewport::wheelEvent(QWheelEvent *event)
{
    const double notches = event->angleDelta().y() / kWheelNotch;
    if (notches == 0.0) {
        event->ignore();
        return;
    }
    m_orbit.zoom(std::pow(kZoomPerWheelNotch, notches));
    cameraMoved();
    event->accept();
}

// The key map is the actions added to this view (Reset Camera's R and Home,
// Inspect's I): their shortcuts. A key that reaches the view unclaimed (the
// shortcut system only acts for an active window) triggers the action that
// names it, so no key is handled in two places.
void Viewport::keyPressEvent(QKeyEvent *event)
{
    const QKeySequence pressed(event->keyCombination());
    for (QAction *action : actions()) {
        if (action->isEnabled() && action->shortcuts().contains(pressed)) {
            action->trigger();
            event->accept();
            return;
        }
    }
    QWidget::keyPressEvent(event);
}

void Viewport::dragEnterEvent(QDragEnterEvent *event)
{
    // Any local file is welcome: an unsupported one is then explained by the
    // window rather than refused without a word.
    if (!localFiles(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void Viewport::dropEvent(QDropEvent *event)
{
    const QStringList paths = localFiles(event->mimeData());
    if (paths.isEmpty())
        return;
    event->acceptProposedAction();
    emit filesDropped(paths);
}

} // namespace phonglab
