// How each object of a frame is drawn: the program for its shading, its
// level of detail, the lights it is drawn with and its uniforms. Apart from
// Renderer.cpp, which holds the renderer's scene and programs and draws the
// frame around these.
#include "Renderer.h"

#include "core/reference/LightBound.h"
#include "core/view/DetailSelection.h"
#include "core/view/ObjectMatrices.h"
#include "render/program/CourseUniforms.h"

#include <QCoreApplication>
#include <algorithm>
#include <glm/gtc/matrix_inverse.hpp>
#include <limits>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language);
// the same context as Renderer.cpp's.
struct RendererObjectsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::Renderer)
};

void Renderer::uploadLights(ShaderProgram &program, std::span<const int> lights)
{
    // Only the lights given are packed; the light count counts them.
    std::vector<glm::dvec3> position, diffuse, specular, attenuation;
    std::vector<double> c1, c2, c3;
    m_uploadedLights.clear();
    for (int i : lights) {
        const PointLight &l = m_scene.lights[std::size_t(i)];
        if (int(position.size()) == kMaxLights)
            break;
        m_uploadedLights.push_back(i);
        position.push_back(l.position); // world coordinates: the shader applies the view
        diffuse.push_back(l.diffuse);
        specular.push_back(l.specular);
        attenuation.push_back(l.attenuation);
        c1.push_back(l.attenuation.x);
        c2.push_back(l.attenuation.y);
        c3.push_back(l.attenuation.z);
    }
    using M = BindingMeaning;
    program.setScalar(M::LightCount, double(position.size()));
    program.setPerLight(M::LightPosition, position, 1.0); // a point: w = 1
    program.setPerLight(M::LightDiffuse, diffuse);
    program.setPerLight(M::LightSpecular, specular);
    program.setPerLight(M::Attenuation, attenuation);
    program.setPerLight(M::C1, c1);
    program.setPerLight(M::C2, c2);
    program.setPerLight(M::C3, c3);
}

// What every object drawn with `program` this frame shares.
void Renderer::bindForFrame(ShaderProgram &program, const glm::dmat4 &view,
                            const glm::dmat4 &projection)
{
    using M = BindingMeaning;
    program.bind();
    program.setExplicitBindings(m_scene.bindings);
    program.setMatrix(M::View, view);
    program.setMatrix(M::Projection, projection);
    program.setMatrix(M::ViewProjection, projection * view);
    program.setVector(M::Eye, glm::dvec3(glm::inverse(view)[3]));
    program.setVector(M::Ambient, m_scene.ambient);
    uploadLights(program, enabledLights(m_scene.lights));
}

ShaderProgram *Renderer::programFor(const SceneObject &object)
{
    const ShadingMethod method = m_scene.shadingOf(object);
    if (method == m_scene.shading)
        return &m_program;
    ShaderProgram &own = m_objectPrograms[method];
    if (!own.isValid()) {
        // A shipped pair that did not build is not read and compiled again
        // every frame; cleanup() forgets the failure.
        const BuildReport built =
            m_failedMethods.contains(method) ? BuildReport() : buildShipped(own, method);
        if (!built.ok) {
            m_failedMethods.insert(method);
            m_drawError =
                RendererObjectsWords::tr("%1: not drawn: the shipped %2 shaders did not build")
                    .arg(object.mesh, shadingName(method));
            return nullptr;
        }
    }
    return &own;
}

void Renderer::drawObjects(const glm::dmat4 &view, const glm::dmat4 &projection,
                           const QSize &pixelSize)
{
    m_lightsLeftOut = 0;
    m_leftOutBound = 0.0;
    m_drawError.clear();
    m_objectLevels.resize(m_scene.objects.size(), -1);
    m_drawn.assign(m_scene.objects.size(), ObjectDraw());
    ShaderProgram *bound = nullptr;
    bool perFace = false;
    for (std::size_t i = 0; i < m_scene.objects.size(); ++i) {
        if (m_options.onlyObject >= 0 && std::size_t(m_options.onlyObject) != i)
            continue;
        const SceneObject &object = m_scene.objects[i];
        const QString key = meshKey(m_scene, object);
        const auto mesh = m_meshes.value(key);
        ShaderProgram *program = mesh ? programFor(object) : nullptr;
        if (!program)
            continue;
        if (program != bound) {
            bindForFrame(*program, view, projection);
            bound = program;
            // A program that reads a face centroid (flat.vert) is drawn from
            // the meshes' face layouts, whoever wrote it.
            perFace = program->readsFacePoint();
        }
        const MeshStats &stats = m_meshInfo.value(key).stats;
        const int level = chooseLevel(i, object, *mesh, stats, pixelSize.height());
        if (perFace) {
            if (Result<> prepared = mesh->prepareFaceLayout(level); !prepared) {
                m_drawError = RendererObjectsWords::tr("%1: not drawn: %2")
                                  .arg(object.mesh, prepared.error());
                continue;
            }
        }
        // Only a closed surface hides its back faces; an open one (a leaf,
        // a plane) must show them.
        if (m_options.cullBackFaces && stats.closed)
            glEnable(GL_CULL_FACE);
        else
            glDisable(GL_CULL_FACE);
        ObjectDraw &drawn = m_drawn[i];
        if (m_options.lightAllowance > 0.0)
            drawn.lightsLeftOut = uploadObjectLights(*program, object, stats);
        // Matrices in double on the CPU, once per draw; the shader gets floats.
        const ObjectMatrices m = ObjectMatrices::make(object.transform.matrix(), view, projection);
        glFrontFace(m.mirrors() ? GL_CW : GL_CCW);
        setObjectUniforms(*program, m, object.material);
        setCourseUniforms(*program, m_scene, m_uploadedLights, object.material, view);
        if (perFace)
            mesh->drawFaces(level);
        else
            mesh->draw(level);
        drawn.level = level;
        drawn.levels = mesh->levelCount();
        drawn.triangles = mesh->indexCount(level) / 3;
        m_trianglesDrawn += drawn.triangles;
    }
}

void Renderer::setObjectUniforms(ShaderProgram &program, const ObjectMatrices &m,
                                 const Material &material)
{
    using M = BindingMeaning;
    program.setMatrix(M::Model, m.model);
    program.setMatrix(M::ModelView, m.modelView);
    program.setMatrix(M::ModelViewProjection, m.projection * m.modelView);
    program.setMatrix(M::NormalMatrix, m.normalMatrix);
    program.setMatrix(M::ModelNormalMatrix, glm::inverseTranspose(glm::dmat3(m.model)));
    program.setVector(M::Ka, material.ka);
    program.setVector(M::Kd, material.kd);
    program.setVector(M::Ks, material.ks);
    program.setScalar(M::Shininess, material.shininess);
    program.setScalar(M::Gain, 1.0);
    program.setVector(M::Gain, glm::dvec3(1.0), 1.0);
}

// The level an object is drawn at: 0 unless it has levels of detail and
// "detail": "auto", else chooseDetailLevel() on this view, with the level it
// had last frame for the hysteresis.
int Renderer::chooseLevel(std::size_t index, const SceneObject &object, const GpuMesh &mesh,
                          const MeshStats &stats, int viewportHeight)
{
    int &current = m_objectLevels[index];
    if (!object.autoDetail || mesh.levelCount() < 2) {
        current = 0;
        return 0;
    }
    const glm::dmat4 model = object.transform.matrix();
    const BoundingSphere bounds =
        boundingSphere(glm::dvec3(stats.boundsMin), glm::dvec3(stats.boundsMax), model);
    // An error in object units grows with the largest scale of the transform.
    const double scale =
        std::max({glm::length(glm::dvec3(model[0])), glm::length(glm::dvec3(model[1])),
                  glm::length(glm::dvec3(model[2]))});
    // A level whose normals could change the shading by more than the
    // allowance is never within the target, however far away, unless the
    // whole object is a few pixels.
    const bool tiny = 2.0 * projectedErrorPx(bounds.radius, bounds, m_scene.camera, viewportHeight)
        <= kTinyObjectPx;
    if (tiny) {
        current = mesh.levelCount() - 1;
        return current;
    }
    std::vector<double> errorsPx;
    for (int l = 0; l < mesh.levelCount(); ++l) {
        const double shading =
            normalErrorBound(mesh.levelNormalDeviation(l), object.material, m_scene.lights, bounds);
        errorsPx.push_back(shading > m_options.detailShadingAllowance
                               ? std::numeric_limits<double>::infinity()
                               : projectedErrorPx(scale * mesh.levelError(l), bounds,
                                                  m_scene.camera, viewportHeight));
    }
    current = chooseDetailLevel(errorsPx, current, m_options.detailPixels);
    return current;
}

int Renderer::uploadObjectLights(ShaderProgram &program, const SceneObject &object,
                                 const MeshStats &stats)
{
    const BoundingSphere bounds = boundingSphere(
        glm::dvec3(stats.boundsMin), glm::dvec3(stats.boundsMax), object.transform.matrix());
    const LightSelection selection =
        selectLights(m_scene.lights, object.material, bounds, m_options.lightAllowance);
    uploadLights(program, selection.kept);
    m_lightsLeftOut += int(selection.leftOut.size());
    m_leftOutBound = std::max(m_leftOutBound, selection.leftOutBound);
    return int(selection.leftOut.size());
}

} // namespace phonglab
