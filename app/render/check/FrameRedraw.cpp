#include "FrameRedraw.h"

#include "render/program/BuildReport.h"

#include <QCoreApplication>

namespace phonglab {

namespace {

struct FrameRedrawWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::FrameRedraw)
};

// The meshes are the same when every object names the same one: then only
// lights, materials, transforms and the camera changed.
bool sameMeshes(const Scene &a, const Scene &b)
{
    if (a.objects.size() != b.objects.size() || a.baseDir != b.baseDir)
        return false;
    for (std::size_t i = 0; i < a.objects.size(); ++i)
        if (meshKey(a, a.objects[i]) != meshKey(b, b.objects[i]))
            return false;
    return true;
}

QString firstError(const BuildReport &report)
{
    for (const ShaderDiagnostic &d : report.diagnostics)
        if (d.isError())
            return d.message;
    return FrameRedrawWords::tr("the driver gave no reason");
}

} // namespace

Result<QImage> FrameRedraw::draw(const FrameRecipe &recipe, QOffscreenSurface *surface,
                                 const std::function<bool()> &keepGoing,
                                 const MeshesLoaded &meshesLoaded)
{
    if (!m_offscreen) {
        auto offscreen = std::make_unique<OffscreenRenderer>();
        if (Result<> created = offscreen->create(surface); !created)
            return fail(created.error());
        m_offscreen = std::move(offscreen);
    }
    m_offscreen->makeCurrent();
    if (Result<> scene = useScene(recipe.scene, keepGoing, meshesLoaded); !scene)
        return fail(scene.error());
    if (Result<> program = useProgram(recipe); !program)
        return fail(program.error());
    Renderer &renderer = m_offscreen->renderer();
    renderer.restoreUniforms(recipe.uniforms);
    Renderer::Options options = recipe.options;
    options.drawLightMarkers = false;
    options.selectedLight = -1;
    renderer.setOptions(options);
    QImage image = m_offscreen->renderImage(recipe.size);
    if (image.isNull())
        return fail(FrameRedrawWords::tr("the frame could not be drawn at %1x%2")
                        .arg(recipe.size.width())
                        .arg(recipe.size.height()));
    return image;
}

Result<> FrameRedraw::useScene(const Scene &scene, const std::function<bool()> &keepGoing,
                               const MeshesLoaded &meshesLoaded)
{
    Renderer &renderer = m_offscreen->renderer();
    if (m_meshesOf && sameMeshes(*m_meshesOf, scene)) {
        renderer.updateSceneParameters(scene);
        return {};
    }
    m_meshesOf.reset();
    SceneMeshes meshes =
        loadSceneMeshes(scene, renderer.loadedKeys(), [&](double) { return keepGoing(); });
    if (!meshes.ok())
        return fail(meshes.error);
    if (meshesLoaded)
        meshesLoaded(meshes);
    if (Result<> set = renderer.setScene(scene, std::move(meshes)); !set)
        return set;
    m_meshesOf = scene;
    m_programOf.reset(); // the scene's bindings name the inputs at link time
    return {};
}

Result<> FrameRedraw::useProgram(const FrameRecipe &recipe)
{
    auto wanted = std::make_tuple(recipe.sources, recipe.scene.shading, recipe.scene.bindings);
    if (m_programOf == wanted)
        return {};
    Renderer &renderer = m_offscreen->renderer();
    const BuildReport built = recipe.sources
        ? renderer.setProgramSources(recipe.sources->vertex, recipe.sources->fragment)
        : renderer.loadShading(recipe.scene.shading);
    if (!built.ok)
        return fail(FrameRedrawWords::tr("the program would not build again for the check: %1")
                        .arg(firstError(built)));
    m_programOf = std::move(wanted);
    return {};
}

PrecisionFinding FrameRedraw::measurePrecision(const FrameRecipe &recipe,
                                               const std::vector<ShaderStageText> &stages,
                                               const Scene &checked, const QImage &checkedImage)
{
    PrecisionFinding finding = declaredPrecision(stages, checked);
    if (finding.declared.isEmpty() || finding.checkedAt != PrecisionRule::Highp || !m_offscreen)
        return finding;
    m_offscreen->makeCurrent();
    m_programOf.reset(); // built as written below
    return phonglab::measurePrecision(*m_offscreen, stages, checked, recipe.size, checkedImage,
                                      &recipe.uniforms);
}

void FrameRedraw::destroy()
{
    m_offscreen.reset();
    m_meshesOf.reset();
    m_programOf.reset();
}

} // namespace phonglab
