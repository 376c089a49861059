#include "PageScene.h"

#include "CapturedVertices.h"
#include "DrawBindings.h"
#include "PageProgram.h"
#include "core/check/ShaderCheck.h"
#include "core/program/BindingsByUse.h"

#include <QCoreApplication>

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>
#include <map>

namespace phonglab {

struct PageSceneWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PageScene)
};

namespace {

using M = BindingMeaning;

// What a draw's uniforms say, by meaning.
class DrawValues
{
public:
    DrawValues(const CapturedOp &draw, const CapturedProgram &program)
        : m_draw(draw)
        , m_bindings(drawBindings(draw))
    {
        bindByUse(m_bindings, program.vertex.toUtf8(), program.fragment.toUtf8());
    }

    const ProgramBindings &bindings() const { return m_bindings; }

    // The value of `meaning` for light `light` (an array's element, or the
    // variable of that light), or nullopt where nothing sends it.
    std::optional<std::vector<double>> value(M meaning, int light = 0) const
    {
        for (const VariableBinding *b : m_bindings.bound(meaning)) {
            if (b->variable.isInput)
                continue;
            const CapturedUniform *u = m_draw.uniform(b->variable.name);
            if (!u)
                continue;
            if (u->isArray && std::size_t(light) < u->values.size())
                return u->values[std::size_t(light)];
            if (!u->isArray && (!isPerLight(meaning) || b->lightIndex == light)
                && !u->values.empty())
                return u->values.front();
        }
        return std::nullopt;
    }
    std::optional<glm::dvec3> vec3(M meaning, int light = 0) const
    {
        const auto v = value(meaning, light);
        if (!v || v->empty())
            return std::nullopt;
        if (v->size() < 3)
            return glm::dvec3(v->front());
        return glm::dvec3((*v)[0], (*v)[1], (*v)[2]);
    }
    std::optional<double> number(M meaning, int light = 0) const
    {
        const auto v = value(meaning, light);
        return v && !v->empty() ? std::optional<double>(v->front()) : std::nullopt;
    }
    std::optional<glm::dmat4> matrix(M meaning) const
    {
        const CapturedUniform *u = uniformMeaning(m_draw, m_bindings, meaning);
        return u ? uniformMatrix(*u) : std::nullopt;
    }

    // How many lights the program is sent: its light count, else the room
    // its per-light uniforms have.
    int lightCount() const
    {
        if (const auto n = number(M::LightCount))
            return std::clamp(int(*n), 0, kMaxLights);
        return std::clamp(m_bindings.lightCapacity().value_or(0), 0, kMaxLights);
    }

private:
    const CapturedOp &m_draw;
    ProgramBindings m_bindings;
};

std::optional<glm::dmat4> projectionOf(const DrawValues &v)
{
    if (const auto p = v.matrix(M::Projection))
        return p;
    const auto mvp = v.matrix(M::ModelViewProjection);
    const auto mv = v.matrix(M::ModelView);
    if (mvp && mv)
        return *mvp * glm::inverse(*mv);
    const auto vp = v.matrix(M::ViewProjection);
    const auto view = v.matrix(M::View);
    if (vp && view)
        return *vp * glm::inverse(*view);
    return std::nullopt;
}

std::optional<glm::dmat4> viewOf(const DrawValues &v)
{
    if (const auto view = v.matrix(M::View))
        return view;
    const auto mv = v.matrix(M::ModelView);
    const auto model = v.matrix(M::Model);
    if (mv && model)
        return *mv * glm::inverse(*model);
    return std::nullopt;
}

std::optional<glm::dmat4> modelViewOf(const DrawValues &v, const glm::dmat4 &projection)
{
    if (const auto mv = v.matrix(M::ModelView))
        return mv;
    const auto model = v.matrix(M::Model);
    if (const auto view = v.matrix(M::View); model && view)
        return *view * *model;
    if (const auto mvp = v.matrix(M::ModelViewProjection))
        return glm::inverse(projection) * *mvp;
    return std::nullopt;
}

// The camera a symmetric perspective projection is, or why not.
Result<Camera> cameraOf(const glm::dmat4 &p, QSize canvas)
{
    const auto zero = [](double x) { return std::abs(x) < 1e-6; };
    if (!zero(p[0][1]) || !zero(p[0][2]) || !zero(p[0][3]) || !zero(p[1][0]) || !zero(p[1][2])
        || !zero(p[1][3]) || !zero(p[2][0]) || !zero(p[2][1]) || std::abs(p[2][3] + 1.0) > 1e-6
        || !zero(p[3][0]) || !zero(p[3][1]) || !zero(p[3][3]) || p[1][1] <= 0 || p[0][0] <= 0)
        return fail(PageSceneWords::tr("the projection sent is not a symmetric perspective"));
    const double aspect = p[1][1] / p[0][0];
    const double canvasAspect = double(canvas.width()) / double(canvas.height());
    if (std::abs(aspect / canvasAspect - 1.0) > 1e-3)
        return fail(PageSceneWords::tr("the projection's aspect (%1) is not the canvas's (%2)")
                        .arg(aspect, 0, 'f', 3)
                        .arg(canvasAspect, 0, 'f', 3));
    Camera camera;
    camera.eye = glm::dvec3(0.0);
    camera.target = glm::dvec3(0.0, 0.0, -1.0);
    camera.up = glm::dvec3(0.0, 1.0, 0.0);
    camera.fovDeg = glm::degrees(2.0 * std::atan(1.0 / p[1][1]));
    camera.nearPlane = p[3][2] / (p[2][2] - 1.0);
    camera.farPlane = p[3][2] / (p[2][2] + 1.0);
    camera.frameObjects = false;
    if (!(camera.nearPlane > 0) || !(camera.farPlane > camera.nearPlane))
        return fail(PageSceneWords::tr("the projection sent has no near and far planes in front"));
    return camera;
}

// The draw's triangles in eye coordinates.
Result<MeshData> meshOf(const PageCapture &capture, const CapturedOp &draw, const DrawValues &v,
                        const glm::dmat4 &modelView)
{
    if (draw.mode != 4 || draw.instances != 1) // TRIANGLES, once
        return fail(PageSceneWords::tr("a draw that is not one list of triangles"));
    const CapturedAttribute *position = attributeMeaning(draw, v.bindings(), M::Position);
    const CapturedAttribute *normal = attributeMeaning(draw, v.bindings(), M::Normal);
    if (!position)
        return fail(PageSceneWords::tr("no vertex input is the position"));
    if (!normal || !normal->enabled)
        return fail(PageSceneWords::tr("drawn without normals"));
    const std::optional<std::vector<qint64>> vertices = drawnVertices(capture, draw);
    if (!vertices)
        return fail(PageSceneWords::tr("a draw past its buffers"));
    const std::vector<glm::dvec4> p = attributeValues(capture, *position, *vertices);
    const std::vector<glm::dvec4> n = attributeValues(capture, *normal, *vertices);
    const glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(modelView));
    MeshData mesh;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::dvec4 eye =
            modelView * glm::dvec4(glm::dvec3(p[i]) / (p[i].w != 0 ? p[i].w : 1.0), 1.0);
        mesh.positions.push_back(glm::vec3(eye));
        // Moved, not normalised: a shader interpolates what its normal matrix
        // gives and normalises per fragment, and the reference does the same.
        mesh.normals.push_back(glm::vec3(normalMatrix * glm::dvec3(n[i])));
        mesh.indices.push_back(std::uint32_t(i));
    }
    mesh.indices.resize(mesh.indices.size() / 3 * 3);
    if (!mesh.isValid())
        return fail(PageSceneWords::tr("its triangles make no mesh"));
    return mesh;
}

// Lights, the ambient light and the material, as the uniforms say them.
// Where a factor is sent as a product (Ia·ka), the other factor is 1.
struct Shading {
    glm::dvec3 ambient{0.0};
    std::vector<PointLight> lights;
    Material material;
};

// The material's colours as sent: its own factors, a single colour, or one
// matrix of all three.
Material sentMaterial(const DrawValues &v)
{
    Material material;
    material.ka = v.vec3(M::Ka).value_or(glm::dvec3(1.0));
    material.kd = v.vec3(M::Kd).value_or(v.vec3(M::MaterialColor).value_or(glm::dvec3(1.0)));
    material.ks = v.vec3(M::Ks).value_or(glm::dvec3(1.0));
    if (const auto color = v.vec3(M::MaterialColor); color && !v.vec3(M::Ka))
        material.ka = *color;
    if (const auto terms = v.matrix(M::MaterialTerms)) {
        material.ka = glm::dvec3((*terms)[0]);
        material.kd = glm::dvec3((*terms)[1]);
        material.ks = glm::dvec3((*terms)[2]);
    }
    return material;
}

// How the lights' colours are sent: as products with the material's, or
// as one matrix of ambient, diffuse and specular.
struct LightFactors {
    bool diffuseProduct = false;
    bool specularProduct = false;
    std::optional<glm::dmat4> lightTerms;
};

Result<glm::dvec3> sentLightPosition(const DrawValues &v, int k,
                                     const std::optional<glm::dmat4> &view)
{
    for (const M meaning : {M::LightPosition, M::LightPositionCamera})
        if (const auto sent = v.value(meaning, k); sent && sent->size() == 4 && (*sent)[3] == 0.0)
            return fail(PageSceneWords::tr("light %1 is a direction (w = 0): the exact image "
                                           "here lights from points")
                            .arg(k + 1));
    if (const auto world = v.vec3(M::LightPosition, k)) {
        // A page that sends no view (a model-view alone) gives its
        // shader no world coordinates: its light is in the only space
        // the shader has, the camera's (Angel's lightPosition).
        return view ? glm::dvec3(*view * glm::dvec4(*world, 1.0)) : *world;
    }
    if (const auto camera = v.vec3(M::LightPositionCamera, k))
        return *camera;
    return fail(PageSceneWords::tr("light %1 has no position sent").arg(k + 1));
}

Result<PointLight> sentLight(const DrawValues &v, int k, const std::optional<glm::dmat4> &view,
                             const LightFactors &f)
{
    PointLight light;
    const Result<glm::dvec3> position = sentLightPosition(v, k, view);
    if (!position)
        return fail(position.error());
    light.position = *position;
    const auto color = v.vec3(M::LightColor, k);
    light.diffuse = v.vec3(f.diffuseProduct ? M::DiffuseProduct : M::LightDiffuse, k)
                        .value_or(color.value_or(f.lightTerms ? glm::dvec3((*f.lightTerms)[1])
                                                              : glm::dvec3(1.0)));
    light.specular = v.vec3(f.specularProduct ? M::SpecularProduct : M::LightSpecular, k)
                         .value_or(color.value_or(f.lightTerms ? glm::dvec3((*f.lightTerms)[2])
                                                               : glm::dvec3(1.0)));
    if (const auto att = v.vec3(M::Attenuation, k))
        light.attenuation = *att;
    else
        light.attenuation =
            glm::dvec3(v.number(M::C1, k).value_or(1.0), v.number(M::C2, k).value_or(0.0),
                       v.number(M::C3, k).value_or(0.0));
    return light;
}

Result<Shading> shadingOf(const DrawValues &v, const std::optional<glm::dmat4> &view)
{
    Shading s;
    s.material = sentMaterial(v);
    const auto shininess = v.number(M::Shininess);
    s.material.shininess = shininess.value_or(1.0);
    const LightFactors f{v.value(M::DiffuseProduct).has_value(),
                         v.value(M::SpecularProduct).has_value(), v.matrix(M::LightTerms)};
    s.ambient = v.vec3(M::Ambient)
                    .value_or(f.lightTerms ? glm::dvec3((*f.lightTerms)[0]) : glm::dvec3(0.0));
    if (const auto product = v.vec3(M::AmbientProduct)) {
        s.ambient = *product;
        s.material.ka = glm::dvec3(1.0);
    }
    if (f.diffuseProduct)
        s.material.kd = glm::dvec3(1.0);
    if (f.specularProduct)
        s.material.ks = glm::dvec3(1.0);
    const bool anySpecular = f.specularProduct || v.value(M::LightSpecular) || v.value(M::Ks)
        || v.value(M::LightColor) || f.lightTerms;
    if (!anySpecular)
        s.material.ks = glm::dvec3(0.0);
    else if (!shininess)
        return fail(PageSceneWords::tr("the specular term has no shininess sent"));
    for (int k = 0; k < v.lightCount(); ++k) {
        const Result<PointLight> light = sentLight(v, k, view, f);
        if (!light)
            return fail(light.error());
        s.lights.push_back(*light);
    }
    if (s.lights.empty())
        return fail(PageSceneWords::tr("no light is sent"));
    return s;
}

// A uniform that changes the image but means nothing PhongLab knows: the
// page's scene cannot be read then. A switch (int, bool) and a texture
// are not colours.
QString unknownUniform(const DrawValues &v)
{
    for (const VariableBinding &b : v.bindings().variables)
        if (!b.meaning && !b.variable.isInput && b.variable.type != GlslType::Int
            && b.variable.type != GlslType::Bool && b.variable.type != GlslType::UInt
            && b.variable.type != GlslType::Other)
            return b.variable.name;
    return {};
}

bool sameLights(const Shading &a, const Shading &b)
{
    return a.ambient == b.ambient && a.lights == b.lights;
}

glm::dvec3 backgroundOf(const PageCapture &capture)
{
    for (const CapturedOp &op : capture.ops)
        if (op.kind == CapturedOp::Kind::Clear && (op.clearMask & 0x4000)) // COLOR_BUFFER_BIT
            return {op.clearColor[0], op.clearColor[1], op.clearColor[2]};
    return glm::dvec3(0.0);
}

} // namespace

Result<PageScene> pageSceneOf(const PageCapture &capture)
{
    const std::optional<PageProgram> lit = litPageProgram(capture);
    if (!lit)
        return fail(PageSceneWords::tr("the page drew no program that lights"));
    PageScene out;
    out.program = lit->program->id;
    out.scene.background = backgroundOf(capture);
    out.scene.camera.frameObjects = false;
    std::optional<Shading> first;
    for (const CapturedOp *draw : capture.draws()) {
        if (draw->program != out.program)
            continue;
        const DrawValues v(*draw, *lit->program);
        if (const QString name = unknownUniform(v); !name.isEmpty())
            return fail(PageSceneWords::tr("uniform %1 changes the image but means nothing "
                                           "PhongLab knows")
                            .arg(name));
        if (draw->state.viewport
            != std::array<int, 4>{0, 0, capture.canvas.width(), capture.canvas.height()})
            return fail(PageSceneWords::tr("a draw's viewport is not the whole canvas"));
        const std::optional<glm::dmat4> projection = projectionOf(v);
        if (!projection)
            return fail(
                PageSceneWords::tr("the page sends no projection of its own (only a product "
                                   "of its matrices)"));
        const Result<Camera> camera = cameraOf(*projection, capture.canvas);
        if (!camera)
            return fail(camera.error());
        const std::optional<glm::dmat4> modelView = modelViewOf(v, *projection);
        if (!modelView)
            return fail(PageSceneWords::tr("the page sends no model-view, nor a view and a model"));
        Result<Shading> shading = shadingOf(v, viewOf(v));
        if (!shading)
            return fail(shading.error());
        if (first && !sameLights(*first, *shading))
            return fail(PageSceneWords::tr("two draws send different lights"));
        Result<MeshData> mesh = meshOf(capture, *draw, v, *modelView);
        if (!mesh)
            return fail(mesh.error());
        if (!first) {
            first = *shading;
            out.scene.camera = *camera;
            out.scene.ambient = shading->ambient;
            out.scene.lights = shading->lights;
        }
        SceneObject object;
        object.mesh = QStringLiteral("page draw %1").arg(out.meshes.size() + 1);
        object.material = shading->material;
        out.scene.objects.push_back(object);
        out.meshes.push_back(std::make_shared<const MeshData>(std::move(*mesh)));
    }
    return out;
}

RgbImage withSnappingAllowed(const RgbImage &browser, const RgbImage &exact)
{
    if (!browser.sameSize(exact))
        return browser;
    RgbImage out = browser;
    const int w = exact.width, h = exact.height;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                const auto at = [&](int px, int py) {
                    return int(exact.bytes[(std::size_t(std::clamp(py, 0, h - 1)) * w
                                            + std::clamp(px, 0, w - 1))
                                               * 3
                                           + c]);
                };
                const int e = at(x, y);
                const int gradient =
                    std::max({std::abs(at(x - 1, y) - e), std::abs(at(x + 1, y) - e),
                              std::abs(at(x, y - 1) - e), std::abs(at(x, y + 1) - e)});
                const int slack = (gradient + kSnapSubpixels - 1) / kSnapSubpixels;
                std::uint8_t &b = out.bytes[(std::size_t(y) * w + x) * 3 + c];
                // Across a jump (a crease of face normals, an object's edge
                // on another) a pixel whose centre lies on the edge may be
                // the neighbour's.
                const int pixel = int(browser.bytes[(std::size_t(y) * w + x) * 3 + c]);
                bool neighbours = false;
                for (const auto &[dx, dy] :
                     {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1},
                      std::pair{-1, -1}, std::pair{1, -1}, std::pair{-1, 1}, std::pair{1, 1}})
                    neighbours = neighbours
                        || (std::abs(at(x + dx, y + dy) - e) > kDefaultCheckToleranceSteps
                            && std::abs(pixel - at(x + dx, y + dy)) <= kDefaultCheckToleranceSteps);
                // What is left is the error beyond the allowance, never less
                // than the error within the tolerance (a PSNR stays honest).
                const int error = std::abs(pixel - e);
                const int tolerance = kDefaultCheckToleranceSteps;
                const int left = error <= tolerance ? error
                    : neighbours                    ? tolerance
                                                    : std::max(tolerance, error - slack);
                b = std::uint8_t(pixel > e ? e + left : e - left);
            }
    return out;
}

RgbImage browserFrame(const PageCapture &capture)
{
    RgbImage image(capture.canvas.width(), capture.canvas.height());
    if (capture.pixels.size() != qsizetype(image.pixelCount()) * 4)
        return {};
    const auto *rgba = reinterpret_cast<const unsigned char *>(capture.pixels.constData());
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                image.bytes[(std::size_t(y) * image.width + x) * 3 + c] =
                    rgba[(std::size_t(image.height - 1 - y) * image.width + x) * 4 + c];
    return image;
}

Result<PageSceneCheck> checkPageScene(const PageCapture &capture)
{
    const Result<PageScene> scene = pageSceneOf(capture);
    if (!scene)
        return fail(scene.error());
    const RgbImage browser = browserFrame(capture);
    if (browser.isNull())
        return fail(PageSceneWords::tr("the page drew nothing to its canvas"));
    const Result<CheckReference> reference =
        makeCheckReference(scene->scene, scene->meshes, browser.width, browser.height);
    if (!reference)
        return fail(reference.error());
    const RgbImage allowed = withSnappingAllowed(browser, reference->exactImage);
    PageSceneCheck out{checkRender(allowed, *reference), reference->exactImage, {}};
    out.heatmap = checkHeatmap(allowed, *reference, out.report.equation);
    if (const CapturedProgram *program = capture.program(scene->program))
        nameWhatTheCodeDoes(out.report, program->vertex.toUtf8(), program->fragment.toUtf8());
    return out;
}

} // namespace phonglab
