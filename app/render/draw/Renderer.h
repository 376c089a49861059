#pragma once
#include "core/scene/Scene.h"
#include "core/support/Result.h"
#include "core/view/DepthRange.h"
#include "core/view/DetailSelection.h"
#include "core/view/ObjectMatrices.h"
#include "mesh/loading/SceneMeshes.h"
#include "render/gl/GpuMesh.h"
#include "render/program/BuildReport.h"
#include "render/program/ShaderProgram.h"

#include <QHash>
#include <QOpenGLExtraFunctions>
#include <QSize>
#include <map>
#include <memory>
#include <set>

namespace phonglab {

// Draws a Scene with the current lighting program into whatever framebuffer
// is bound. Knows nothing about widgets: the viewport, the offscreen target
// and the tests all drive this class. Every call needs the context current;
// call cleanup() before that context is destroyed.
class Renderer : protected QOpenGLExtraFunctions
{
public:
    struct Options {
        bool drawLightMarkers = false;
        bool cullBackFaces = true; // builtin and imported meshes are closed
        int selectedLight = -1;    // its marker is drawn larger (the Lights dock's selection)
        // Lights whose bounded contribution to an object sums below this
        // (linear intensity; LightBound.h) are left out of its draw. 0: none.
        double lightAllowance = 0.0;
        // "detail": "auto" objects take the coarsest level whose error
        // spans at most this many pixels (DetailSelection.h).
        double detailPixels = kDefaultDetailPixels;
        // ... and whose normals are close enough that no pixel's shading
        // can change by more than this (linear intensity; normalErrorBound()).
        double detailShadingAllowance = 0.5 / 255.0;
        // When ≥ 0, only this scene object is drawn (the bench times one
        // object alone for the per-object fit).
        int onlyObject = -1;
    };

    // How one object was drawn in the last frame.
    struct ObjectDraw {
        int level = 0;         // level of detail drawn; 0 = the full mesh
        int levels = 1;        // levels the object's mesh has (1: none built)
        qint64 triangles = 0;  // 0 when it was not drawn
        int lightsLeftOut = 0; // lights its draw did without
    };

    Renderer();
    ~Renderer();
    Renderer(const Renderer &) = delete;
    Renderer &operator=(const Renderer &) = delete;

    // Prepares GL state and the light-marker program. A failure when the
    // context cannot run PhongLab's shaders.
    Result<> initialize();
    void cleanup();

    // Loads every object's mesh and uploads it. On failure the previous
    // scene stays. Blocks while loading: the GUI loads with
    // loadSceneMeshes() on a worker thread and calls the overload below.
    Result<> setScene(const Scene &scene);
    // Uploads meshes loaded elsewhere (loadSceneMeshes(scene, loadedKeys()))
    // and switches to `scene`. Frees each uploaded MeshData's CPU copy.
    Result<> setScene(const Scene &scene, SceneMeshes &&meshes);
    QSet<QString> loadedKeys() const;
    // Statistics and warnings of the meshes in use, by meshKey().
    const QHash<QString, SceneMeshes::Entry> &meshInfo() const { return m_meshInfo; }
    const Scene &scene() const { return m_scene; }
    // Changes camera/lights/materials without touching meshes (cheap; for
    // interaction). Objects must name the same meshes as the current scene.
    void updateSceneParameters(const Scene &scene);

    // The lighting program: the shipped one for a shading method, or any
    // user sources. On failure the previous program keeps rendering.
    BuildReport loadShading(ShadingMethod method);
    BuildReport setProgramSources(const ShaderSource &vertex, const ShaderSource &fragment);
    // Switches to a program linked elsewhere (a ProgramBuilder on a context
    // sharing this one's objects) and owns it from then on. Uniforms the
    // user set on the old program carry over where name and type match; the
    // ones the renderer drives are set again on every frame anyway.
    void adoptProgram(GlProgram program);
    bool hasProgram() const { return m_program.isValid(); }
    // A trial of a new program (LiveShaderController): puts `program` in
    // place with the current one's uniform values, handing the current one
    // back through `program`; a second call undoes the first.
    void exchangeProgram(GlProgram &program);
    // Sets the program's uniforms to `values` (another program's snapshot
    // of the same sources): they win over the scene's values still pending.
    void restoreUniforms(const UniformSnapshot &values);
    ShaderProgram &program() { return m_program; }

    void setOptions(const Options &options) { m_options = options; }
    const Options &options() const { return m_options; }

    // Renders one frame into a pixelSize framebuffer (device pixels).
    void render(const QSize &pixelSize);
    qint64 trianglesDrawn() const { return m_trianglesDrawn; }
    // Light terms the last frame left out (one per light per object), and
    // the largest sum of bounds left out of any one object.
    int lightsLeftOut() const { return m_lightsLeftOut; }
    // Per scene object, in order.
    const std::vector<ObjectDraw> &objectDraws() const { return m_drawn; }
    double leftOutBound() const { return m_leftOutBound; }
    // Why the last frame left an object out ("<mesh>: not drawn: ..."), or
    // empty. Only flat shading's face layout can fail at draw time.
    const QString &drawError() const { return m_drawError; }
    // The near and far planes the last frame was drawn with: the camera's,
    // fitted to what the scene occupies (DepthRange.h).
    const DepthRange &depthRange() const { return m_depthRange; }

private:
    void drawObjects(const glm::dmat4 &view, const glm::dmat4 &projection, const QSize &pixelSize);
    BuildReport buildShipped(ShaderProgram &program, ShadingMethod method);
    ShaderProgram *programFor(const SceneObject &object);
    void bindForFrame(ShaderProgram &program, const glm::dmat4 &view, const glm::dmat4 &projection);
    void uploadLights(ShaderProgram &program, std::span<const int> lights);
    void setObjectUniforms(ShaderProgram &program, const ObjectMatrices &matrices,
                           const Material &material);
    int uploadObjectLights(ShaderProgram &program, const SceneObject &object,
                           const MeshStats &stats);
    int chooseLevel(std::size_t index, const SceneObject &object, const GpuMesh &mesh,
                    const MeshStats &stats, int viewportHeight);
    void applySceneUniforms();
    void drawLightMarkers(const glm::dmat4 &view, const glm::dmat4 &projection);
    std::vector<BoundingSphere> boundingSpheres() const;

    bool m_initialized = false;
    Options m_options;
    Scene m_scene;
    ShaderProgram m_program;
    std::vector<int> m_uploadedLights; // the scene's lights uploadLights() packed last
    // Shipped programs of the methods objects have of their own ("shading"
    // in an "objects" entry), built on first use.
    std::map<ShadingMethod, ShaderProgram> m_objectPrograms;
    std::set<ShadingMethod> m_failedMethods;
    ShaderProgram m_markerProgram;
    GpuMesh m_markerMesh;
    QHash<QString, std::shared_ptr<GpuMesh>> m_meshes; // by meshKey()
    QHash<QString, SceneMeshes::Entry> m_meshInfo;     // stats and warnings; no CPU mesh
    qint64 m_trianglesDrawn = 0;
    std::vector<int> m_objectLevels; // per object: the level drawn last frame, -1 none yet
    std::vector<ObjectDraw> m_drawn;
    int m_lightsLeftOut = 0;
    double m_leftOutBound = 0.0;
    QString m_drawError;
    DepthRange m_depthRange;
    // The scene's values for the shader's own uniforms, until a program that
    // declares them is in place (a scene may open before its shaders build).
    std::map<QString, std::vector<double>> m_pendingUniforms;
    GLuint m_pendingTriedProgram = 0; // compared with the program's name only, never freed
};

} // namespace phonglab
