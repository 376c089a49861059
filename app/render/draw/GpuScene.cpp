#include "GpuScene.h"

#include "core/view/CameraFraming.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <algorithm>

namespace phonglab {

Result<> GpuScene::initialize()
{
    if (const Result<> initialized = m_renderer.initialize(); !initialized)
        return initialized;
    m_renderer.setOptions(m_options);
    m_initialized = true;
    return {};
}

Result<> GpuScene::uploadShown()
{
    // Pending meshes are there after the first show; after a context change
    // (the widget moved to another window) the scene is loaded again here.
    SceneMeshes meshes = m_pendingMeshes ? std::move(*m_pendingMeshes) : loadSceneMeshes(m_scene);
    m_pendingMeshes.reset();
    if (const Result<> uploaded = upload(currentScene(), std::move(meshes)).result; !uploaded)
        return uploaded;
    m_parametersDirty = false;
    return {};
}

void GpuScene::release()
{
    if (m_initialized)
        m_renderer.cleanup();
    m_initialized = false;
    m_ready = false;
}

// The shading program goes first because it is the cheap one to restore if
// the meshes then fail.
GpuScene::Upload GpuScene::upload(const Scene &scene, SceneMeshes &&meshes)
{
    Upload upload;
    const GLuint programBefore = m_renderer.program().id();
    const ShadingMethod previousShading = m_renderer.scene().shading;
    const bool reloadShading = !m_renderer.hasProgram() || scene.shading != previousShading;
    if (reloadShading) {
        if (const BuildReport built = m_renderer.loadShading(scene.shading); !built.ok) {
            // The renderer keeps its previous program.
            upload.result = fail(tr("Cannot build the %1 shading program:\n%2")
                                     .arg(shadingName(scene.shading), built.errorSummary()));
            return upload;
        }
    }
    upload.result = m_renderer.setScene(scene, std::move(meshes));
    if (!upload.result && reloadShading && scene.shading != previousShading)
        m_renderer.loadShading(previousShading);
    if (m_renderer.program().id() != programBefore)
        upload.shippedProgram = upload.result ? scene.shading : m_scene.shading;
    if (upload.result)
        m_ready = true;
    return upload;
}

Result<> GpuScene::keepUntilInitialized(const Scene &scene, SceneMeshes &&meshes)
{
    for (const SceneObject &object : scene.objects) {
        if (!meshes.entries.contains(meshKey(scene, object)))
            return fail(tr("%1: mesh was not loaded").arg(scene.resolveMeshPath(object.mesh)));
    }
    m_pendingMeshes = std::move(meshes);
    return {};
}

void GpuScene::show(const Scene &scene)
{
    m_scene = scene;
    m_parametersDirty = true;
}

QSet<QString> GpuScene::loadedKeys() const
{
    // Pending meshes are not counted: a new pending set replaces them.
    return m_initialized ? m_renderer.loadedKeys() : QSet<QString>();
}

const QHash<QString, SceneMeshes::Entry> &GpuScene::meshInfo() const
{
    static const QHash<QString, SceneMeshes::Entry> none;
    if (m_initialized)
        return m_renderer.meshInfo();
    return m_pendingMeshes ? m_pendingMeshes->entries : none;
}

Scene GpuScene::currentScene() const
{
    Scene scene = m_scene;
    scene.camera = m_orbit.camera();
    // Moved by the user: a composed shot, to be shown as it is.
    scene.camera.frameObjects = m_scene.camera.frameObjects && m_cameraFramed;
    return scene;
}

Scene GpuScene::renderedScene() const
{
    Scene scene = currentScene();
    // Disabled lights are not sent to the shader, so they leave room for it.
    const int enabledLights = scene.enabledLightCount();
    if (m_headlight && enabledLights < kMaxLights) {
        PointLight head;
        head.position = scene.camera.eye; // moves with every orbit, pan and zoom
        scene.lights.push_back(head);
    }
    return scene;
}

// What Save writes: the scene's own camera until the user moves it (a camera
// moved back only to fit this view's shape is not the scene's).
Camera GpuScene::cameraToSave() const
{
    return m_cameraFramed ? m_scene.camera : currentScene().camera;
}

bool GpuScene::frame(const QSize &pixels)
{
    const double aspect = pixels.isEmpty() ? 0.0 : double(pixels.width()) / pixels.height();
    const Camera framed = m_scene.camera.frameObjects
        ? framedCamera(m_scene.camera, objectBoundsCorners(m_scene, meshInfo()), aspect)
        : m_scene.camera;
    m_cameraFramed = true;
    m_parametersDirty = true;
    if (framed == m_orbit.original() && framed == m_orbit.camera())
        return false;
    m_orbit.setOriginal(framed);
    return true;
}

OrbitCamera &GpuScene::orbitByUser()
{
    m_cameraFramed = false; // a resize leaves the camera where the user put it
    m_parametersDirty = true;
    return m_orbit;
}

void GpuScene::resetCamera()
{
    m_orbit.reset();
    m_parametersDirty = true;
}

void GpuScene::moveLight(int index, const glm::dvec3 &position)
{
    m_scene.lights[index].position = position;
    m_parametersDirty = true;
}

void GpuScene::setShading(ShadingMethod method)
{
    m_scene.shading = method;
    m_parametersDirty = true;
    // The renderer's copy decides whether a later scene must reload its
    // program, so it has to follow now rather than at the next draw.
    if (m_ready)
        sendChangedParameters();
}

void GpuScene::setParameters(const Scene &scene)
{
    m_scene.ambient = scene.ambient;
    m_scene.lights = scene.lights;
    const size_t count = std::min(m_scene.objects.size(), scene.objects.size());
    for (size_t i = 0; i < count; ++i) {
        m_scene.objects[i].material = scene.objects[i].material;
        m_scene.objects[i].transform = scene.objects[i].transform;
    }
    m_parametersDirty = true;
}

void GpuScene::setBindings(const ExplicitBindings &bindings)
{
    m_scene.bindings = bindings;
    m_parametersDirty = true;
}

void GpuScene::setHeadlight(bool on)
{
    m_headlight = on;
    m_parametersDirty = true;
}

void GpuScene::setOptions(const Renderer::Options &options)
{
    m_options = options;
    // Reaches the renderer with the next frame, like the parameters: while
    // the context is lent, another thread may be drawing with it.
    m_parametersDirty = true;
}

bool GpuScene::draw(const QSize &pixels)
{
    if (!m_ready) {
        // Nothing to draw (GL failed and was reported): show the background.
        QOpenGLFunctions *f = QOpenGLContext::currentContext()->functions();
        const glm::dvec3 bg = m_scene.background;
        f->glClearColor(float(bg.r), float(bg.g), float(bg.b), 1.0f);
        f->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return false;
    }
    sendChangedParameters();
    m_renderer.render(pixels);
    return true;
}

UniformSnapshot GpuScene::programSnapshot()
{
    return m_ready ? m_renderer.program().snapshot() : UniformSnapshot{};
}

void GpuScene::sendChangedParameters()
{
    if (!m_parametersDirty)
        return;
    m_renderer.updateSceneParameters(renderedScene());
    m_renderer.setOptions(m_options);
    m_parametersDirty = false;
}

} // namespace phonglab
