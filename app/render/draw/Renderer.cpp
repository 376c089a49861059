#include "Renderer.h"

#include "core/scene/ResourcePaths.h"
#include "mesh/import/BuiltinMeshes.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct RendererWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::Renderer)
};

namespace {
constexpr double kMarkerRadius = 0.06; // world units
} // namespace

Renderer::Renderer() = default;
Renderer::~Renderer() = default;

Result<> Renderer::initialize()
{
    initializeOpenGLFunctions();
    const Result<StageSources> markerFiles = readStageFiles(
        shaderPath(QStringLiteral("marker.vert")), shaderPath(QStringLiteral("marker.frag")));
    if (!markerFiles)
        return fail(markerFiles.error());
    // Set as every program's uniforms are: by what they mean.
    m_markerProgram.setExplicitBindings(
        {{QStringLiteral("mvpMatrix"), BindingMeaning::ModelViewProjection},
         {QStringLiteral("color"), BindingMeaning::MaterialColor}});
    const BuildReport marker = m_markerProgram.build(markerFiles->vertex, markerFiles->fragment);
    if (!marker.ok)
        return fail(RendererWords::tr("cannot build the light-marker program:\n")
                    + marker.errorSummary());
    if (Result<> uploaded = m_markerMesh.upload(makeUvSphere(16, 8)); !uploaded)
        return fail(RendererWords::tr("cannot upload the light marker: ") + uploaded.error());
    m_initialized = true;
    return {};
}

void Renderer::cleanup()
{
    if (!m_initialized)
        return;
    m_program.destroy();
    for (auto &[method, program] : m_objectPrograms)
        program.destroy();
    m_objectPrograms.clear();
    m_failedMethods.clear();
    m_markerProgram.destroy();
    m_markerMesh.destroy();
    for (auto &mesh : m_meshes)
        mesh->destroy();
    m_meshes.clear();
    m_meshInfo.clear();
    m_initialized = false;
}

Result<> Renderer::setScene(const Scene &scene)
{
    SceneMeshes meshes = loadSceneMeshes(scene, loadedKeys());
    return setScene(scene, std::move(meshes));
}

QSet<QString> Renderer::loadedKeys() const
{
    QSet<QString> keys;
    for (auto it = m_meshes.begin(); it != m_meshes.end(); ++it)
        keys.insert(it.key());
    return keys;
}

Result<> Renderer::setScene(const Scene &scene, SceneMeshes &&loaded)
{
    if (!loaded.ok())
        return fail(loaded.error);
    QHash<QString, std::shared_ptr<GpuMesh>> meshes;
    QHash<QString, SceneMeshes::Entry> info;
    for (const SceneObject &object : scene.objects) {
        const QString key = meshKey(scene, object);
        if (meshes.contains(key))
            continue;
        if (auto existing = m_meshes.value(key)) {
            meshes.insert(key, existing);
            info.insert(key, m_meshInfo.value(key));
            continue;
        }
        // On failure the meshes uploaded here go; the scene shown stays.
        const auto refuse = [&](const QString &why) {
            for (auto m = meshes.begin(); m != meshes.end(); ++m)
                if (!m_meshes.contains(m.key()))
                    m.value()->destroy();
            return fail(QStringLiteral("%1: %2").arg(key, why));
        };
        auto it = loaded.entries.find(key);
        if (it == loaded.entries.end() || !it->mesh)
            return refuse(RendererWords::tr("mesh was not loaded"));
        auto gpu = std::make_shared<GpuMesh>();
        if (Result<> uploaded = gpu->upload(*it->mesh, it->levels.get()); !uploaded)
            return refuse(uploaded.error());
        it->mesh.reset(); // the GPU has it now
        it->levels.reset();
        meshes.insert(key, gpu);
        info.insert(key, *it);
    }
    for (auto it = m_meshes.begin(); it != m_meshes.end(); ++it)
        if (!meshes.contains(it.key()))
            it.value()->destroy();
    m_meshes = std::move(meshes);
    m_meshInfo = std::move(info);
    m_scene = scene;
    m_program.setExplicitBindings(m_scene.bindings);
    m_pendingUniforms = scene.uniforms;
    m_pendingTriedProgram = 0;
    m_objectLevels.clear(); // each object starts at the level its first view allows
    return {};
}

void Renderer::updateSceneParameters(const Scene &scene)
{
    m_scene = scene;
    m_program.setExplicitBindings(m_scene.bindings); // a "bound to" choice: uniforms only
}

BuildReport Renderer::loadShading(ShadingMethod method)
{
    return buildShipped(m_program, method);
}

BuildReport Renderer::buildShipped(ShaderProgram &program, ShadingMethod method)
{
    const Result<StageSources> shipped = readShippedStages(method);
    if (!shipped) {
        BuildReport failed;
        failed.diagnostics.push_back(
            {BuildStep::Link, ShaderDiagnostic::Severity::Error, {}, 0, 0, shipped.error()});
        return failed;
    }
    return program.build(shipped->vertex, shipped->fragment);
}

BuildReport Renderer::setProgramSources(const ShaderSource &vertex, const ShaderSource &fragment)
{
    // The scene's word on the inputs' names counts at link time, its
    // course's options at compile time.
    m_program.setExplicitBindings(m_scene.bindings);
    m_program.setCourseOptions(m_scene.course);
    return m_program.build(vertex, fragment);
}

void Renderer::adoptProgram(GlProgram program)
{
    const UniformSnapshot kept = m_program.snapshot();
    m_program.setExplicitBindings(m_scene.bindings);
    m_program.adopt(std::move(program));
    m_program.restore(kept);
}

void Renderer::exchangeProgram(GlProgram &program)
{
    const UniformSnapshot kept = m_program.snapshot();
    m_program.exchange(program);
    m_program.restore(kept);
}

void Renderer::restoreUniforms(const UniformSnapshot &values)
{
    m_pendingUniforms.clear();
    m_program.restore(values);
}

// Each pending value is written once, into the first program that declares
// it with as many components; from then on the program keeps it and
// rebuilds carry it (ShaderProgram::snapshot/restore).
void Renderer::applySceneUniforms()
{
    if (m_pendingUniforms.empty() || m_program.id() == m_pendingTriedProgram)
        return;
    m_pendingTriedProgram = m_program.id();
    const UniformSnapshot active = m_program.snapshot();
    UniformSnapshot values;
    for (auto it = m_pendingUniforms.begin(); it != m_pendingUniforms.end();) {
        const UniformValue *current = active.find(it->first.toUtf8());
        if (!current || current->components != int(it->second.size())) {
            ++it;
            continue;
        }
        UniformValue v = *current;
        for (int i = 0; i < v.components; ++i) {
            v.floats[i] = GLfloat(it->second[i]);
            v.ints[i] = GLint(std::lround(it->second[i]));
            v.uints[i] = GLuint(std::max(0L, std::lround(it->second[i])));
        }
        values.values.push_back(v);
        it = m_pendingUniforms.erase(it);
    }
    m_program.restore(values);
}

void Renderer::render(const QSize &pixelSize)
{
    const glm::dvec3 bg = m_scene.background;
    glViewport(0, 0, pixelSize.width(), pixelSize.height());
    // The clear too stays in the frame's corner: a smaller frame drawn into
    // a larger framebuffer (a trial, the check's picture) would otherwise
    // pay for clearing all of it, on llvmpipe most of its time.
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, pixelSize.width(), pixelSize.height());
    glClearColor(float(bg.r), float(bg.g), float(bg.b), 1.0f);
    glClearDepthf(1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    m_trianglesDrawn = 0;
    if (!m_program.isValid() || pixelSize.isEmpty()) {
        m_drawn.assign(m_scene.objects.size(), ObjectDraw());
        m_lightsLeftOut = 0;
        m_leftOutBound = 0.0;
        glDisable(GL_SCISSOR_TEST);
        return;
    }
    applySceneUniforms();

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glCullFace(GL_BACK);

    const double aspect = double(pixelSize.width()) / double(pixelSize.height());
    const glm::dmat4 view = m_scene.camera.viewMatrix();
    m_depthRange = fitDepthRange(m_scene.camera, boundingSpheres());
    const glm::dmat4 projection =
        m_scene.camera.projectionMatrix(aspect, m_depthRange.nearPlane, m_depthRange.farPlane);
    drawObjects(view, projection, pixelSize);
    if (m_options.drawLightMarkers)
        drawLightMarkers(view, projection);
    glUseProgram(0);
    glDisable(GL_SCISSOR_TEST);
}

std::vector<BoundingSphere> Renderer::boundingSpheres() const
{
    std::vector<BoundingSphere> spheres;
    for (const SceneObject &object : m_scene.objects) {
        const QString key = meshKey(m_scene, object);
        if (!m_meshes.contains(key))
            continue;
        const MeshStats &stats = m_meshInfo.value(key).stats;
        spheres.push_back(boundingSphere(glm::dvec3(stats.boundsMin), glm::dvec3(stats.boundsMax),
                                         object.transform.matrix()));
    }
    if (m_options.drawLightMarkers)
        for (const PointLight &light : m_scene.lights)
            spheres.push_back({light.position, 2.0 * kMarkerRadius});
    return spheres;
}

void Renderer::drawLightMarkers(const glm::dmat4 &view, const glm::dmat4 &projection)
{
    m_markerProgram.bind();
    for (int i = 0; i < int(m_scene.lights.size()); ++i) {
        const PointLight &light = m_scene.lights[i];
        const double r = i == m_options.selectedLight ? 2.0 * kMarkerRadius : kMarkerRadius;
        const glm::dmat4 model = glm::dmat4(r, 0, 0, 0, 0, r, 0, 0, 0, 0, r, 0, light.position.x,
                                            light.position.y, light.position.z, 1);
        // Show the light's hue even when its intensity is above 1 or very dim.
        const double peak = std::max({light.diffuse.r, light.diffuse.g, light.diffuse.b, 1e-6});
        m_markerProgram.setMatrix(BindingMeaning::ModelViewProjection, projection * view * model);
        // A disabled light keeps its marker (it can still be picked and
        // dragged), drawn dimmed to a quarter of its hue.
        const double dim = light.enabled ? 1.0 : 0.25;
        m_markerProgram.setVector(BindingMeaning::MaterialColor, dim * light.diffuse / peak);
        m_markerMesh.draw();
    }
}

} // namespace phonglab
