// Viewport: the face of the view's rooms (ViewportSurface, ViewportInput,
// GpuScene, WidgetOverlay), tying their changes to each other and to the
// signals the window listens to.
#include "Viewport.h"

#include "CurrentContext.h"
#include "ViewportInput.h"
#include "WidgetOverlay.h"
#include "render/draw/FramebufferImage.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QResizeEvent>
#include <QWindow>

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
    , m_surface(new ViewportSurface(this, this, presentOffThread))
    , m_input(new ViewportInput(this, m_gpu))
    , m_overlay(new WidgetOverlay(this, m_surface->container()))
{
    connect(m_surface, &ViewportSurface::started, this, &Viewport::initializeGl);
    connect(m_surface, &ViewportSurface::failed, this, &Viewport::renderError);
    connect(m_surface, &ViewportSurface::frameSwapped, this, &Viewport::frameSwapped);
    connect(m_surface, &ViewportSurface::framesHeldAfter, this, &Viewport::framesHeldAfter);
    connect(m_surface, &ViewportSurface::frameTimed, this, [this](double meanMs) {
        emit frameRendered(meanMs, m_gpu.renderer().trianglesDrawn());
    });

    connect(m_input, &ViewportInput::userActed, this, &Viewport::resumeFrames);
    connect(m_input, &ViewportInput::cameraMoved, this, &Viewport::cameraMoved);
    connect(m_input, &ViewportInput::lightMoved, this, [this] {
        requestFrame();
        emit sceneParametersChanged();
    });
    connect(m_input, &ViewportInput::lightPicked, this, [this](int index) {
        setSelectedLight(index);
        emit lightPicked(index);
    });
    connect(m_input, &ViewportInput::lightDragged, this, &Viewport::lightDragged);
    connect(m_input, &ViewportInput::filesDropped, this, &Viewport::filesDropped);

    connect(m_overlay, &WidgetOverlay::changed, this, &Viewport::requestFrame);
}

Viewport::~Viewport()
{
    cleanup();
}

void Viewport::makeCurrent()
{
    m_surface->makeCurrent();
}

void Viewport::doneCurrent()
{
    m_surface->doneCurrent();
}

std::optional<LentContext> Viewport::lendContext(QThread *borrower)
{
    return m_gpu.isInitialized() ? m_surface->lendContext(borrower) : std::nullopt;
}

bool Viewport::takeBackContext(int timeoutMs)
{
    return m_surface->takeBackContext(timeoutMs);
}

QImage Viewport::grabFramebuffer()
{
    return m_surface->grabFrame();
}

void Viewport::resumeFrames()
{
    m_surface->resumeFrames();
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
    if (m_gpu.isInitialized()) {
        GpuScene::Upload upload;
        {
            const CurrentContext current(*this);
            upload = m_gpu.upload(scene, std::move(meshes));
        }
        if (upload.shippedProgram)
            emit shippedProgramLoaded(*upload.shippedProgram);
        if (!upload.result)
            return upload.result;
    } else if (Result<> kept = m_gpu.keepUntilInitialized(scene, std::move(meshes)); !kept) {
        // A scene accepted here must not fail later in the GL start.
        return kept;
    }
    showUploaded(scene);
    return {};
}

QSet<QString> Viewport::loadedKeys() const
{
    return m_gpu.loadedKeys();
}

const QHash<QString, SceneMeshes::Entry> &Viewport::meshInfo() const
{
    return m_gpu.meshInfo();
}

void Viewport::showUploaded(const Scene &scene)
{
    m_gpu.show(scene);
    m_surface->releaseHold(); // a new scene is drawn once at least
    m_gpu.frame(pixelSize());
    cameraMoved();
    emit sceneChanged();
}

Camera Viewport::cameraToSave() const
{
    return m_gpu.cameraToSave();
}

Scene Viewport::currentScene() const
{
    return m_gpu.currentScene();
}

Scene Viewport::renderedScene() const
{
    return m_gpu.renderedScene();
}

// The frame window covers this widget, so the cursor shown over the view
// is that window's.
bool Viewport::event(QEvent *event)
{
    if (event->type() == QEvent::CursorChange)
        m_surface->window()->setCursor(cursor());
    return QWidget::event(event);
}

void Viewport::resizeEvent(QResizeEvent *event)
{
    m_surface->container()->setGeometry(rect());
    // Until the user moves the camera, it keeps every object in view.
    if (m_gpu.isCameraFramed() && m_gpu.frame(pixelSize()))
        cameraMoved();
    requestFrame(); // not every platform exposes a resized window again
    QWidget::resizeEvent(event);
}

void Viewport::setSceneParameters(const Scene &scene)
{
    m_gpu.setParameters(scene);
    const int lights = int(scene.lights.size());
    if (selectedLight() >= lights)
        setSelectedLight(lights - 1);
    parametersChanged();
    emit sceneParametersChanged();
}

void Viewport::setHeadlight(bool on)
{
    m_gpu.setHeadlight(on);
    parametersChanged();
    emit headlightChanged(on);
}

void Viewport::setSelectedLight(int index)
{
    Renderer::Options options = m_gpu.options();
    options.selectedLight = index;
    m_gpu.setOptions(options);
    requestFrame();
}

void Viewport::resetCamera()
{
    m_gpu.resetCamera();
    m_gpu.frame(pixelSize());
    cameraMoved();
}

void Viewport::setReductionAllowance(double allowance, bool leaveOutLights)
{
    Renderer::Options options = m_gpu.options();
    options.lightAllowance = leaveOutLights ? allowance : 0.0;
    options.detailShadingAllowance = allowance;
    m_gpu.setOptions(options);
    requestFrame();
}

void Viewport::setShowLightMarkers(bool show)
{
    Renderer::Options options = m_gpu.options();
    options.drawLightMarkers = show;
    m_gpu.setOptions(options);
    requestFrame();
}

QImage Viewport::renderImage(const QSize &pixelSize, bool lightMarkers)
{
    if (!m_gpu.isReady() || pixelSize.isEmpty())
        return {};
    const CurrentContext current(*this);
    Renderer::Options options = m_gpu.options();
    options.drawLightMarkers = options.drawLightMarkers && lightMarkers;
    // Up to the window's size (the live check): drawn into a corner of the
    // window's back buffer, the framebuffer whose shader variant the lent
    // warm-up compiled off the GUI thread; any other framebuffer would cost
    // llvmpipe another compile here, ~80 ms after every edit. Larger (an
    // export): a framebuffer object with the view's samples.
    if (!m_surface->backBufferHolds(pixelSize))
        return m_gpu.drawWith(options, [&](Renderer &renderer) {
            return drawIntoImage(renderer, pixelSize, m_surface->framebufferSamples());
        });
    QOpenGLContext *gl = context();
    return m_gpu.drawWith(options, [&](Renderer &renderer) {
        gl->functions()->glBindFramebuffer(GL_FRAMEBUFFER, gl->defaultFramebufferObject());
        renderer.render(pixelSize);
        // What is on screen stays: every frame redraws the whole back buffer
        // before it swaps.
        return m_surface->readBackBuffer(pixelSize).convertToFormat(QImage::Format_RGB32);
    });
}

bool Viewport::drawScene(const QSize &pixels)
{
    return m_gpu.draw(pixels);
}

void Viewport::drawOverlays(const QSize &pixels)
{
    m_overlay->draw(pixels);
}

std::function<void(const QSize &)> Viewport::drawForBorrower(const QSize &pixels)
{
    if (!m_gpu.isReady() || m_gpu.hasUnsentChanges())
        return {};
    std::optional<QImage> overlay = m_overlay->paintedFor(pixels);
    if (!overlay)
        return {};
    // The renderer and the overlay's layer are left alone by this thread
    // while the context is out; the image is a copy of the one painted.
    return [renderer = &m_gpu.renderer(), layer = m_overlay,
            image = std::move(*overlay)](const QSize &size) {
        renderer->render(size);
        if (!image.isNull())
            layer->drawPainted(image, size);
    };
}

// Once, with the context just made and current.
void Viewport::initializeGl()
{
    m_glRendererName = contextDescription(context());
    emit glRendererChanged(m_glRendererName);
    if (const Result<> initialized = m_gpu.initialize(); !initialized) {
        emit renderError(
            tr("Cannot render with %1: %2").arg(m_glRendererName, initialized.error()));
        return;
    }
    if (const Result<> uploaded = m_gpu.uploadShown(); !uploaded) {
        emit renderError(uploaded.error());
        return;
    }
    emit sceneChanged(); // meshInfo() now comes from the renderer
    emit glInitialized();
}

void Viewport::cleanup()
{
    if (!m_gpu.isInitialized())
        return;
    emit glAboutToBeReleased(); // the borrower stops, and gives the context back
    if (!m_surface->takeBackContext(kGiveBackTimeoutMs)) {
        qWarning("phonglab: the viewport's OpenGL context was not given back; its resources "
                 "are left");
        return;
    }
    makeCurrent();
    m_surface->destroyGlObjects();
    m_overlay->destroy();
    m_gpu.release();
    doneCurrent();
}

void Viewport::parametersChanged()
{
    m_gpu.markChanged();
    requestFrame();
}

void Viewport::cameraMoved()
{
    parametersChanged();
    emit cameraChanged();
}

} // namespace phonglab
