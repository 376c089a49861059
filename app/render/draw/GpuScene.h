#pragma once
#include "Renderer.h"
#include "core/scene/Scene.h"
#include "core/view/OrbitCamera.h"
#include "render/program/UniformSnapshot.h"

#include <QCoreApplication>
#include <QSize>
#include <optional>

namespace phonglab {

// The viewport's scene on the GPU: the scene as loaded, the camera as
// orbited, the renderer holding its meshes and program, and how it draws.
// Knows nothing of windows or threads: the methods marked "GL" need the
// viewport's context current (Viewport makes it so), the others are plain
// state. Parameter changes are collected and reach the renderer once, just
// before the next draw.
class GpuScene
{
    Q_DECLARE_TR_FUNCTIONS(phonglab::GpuScene)

public:
    // GL: the renderer's resources.
    Result<> initialize();
    // GL, once initialised: the scene shown, with the meshes kept from before
    // GL was up (or loaded again after a context change).
    Result<> uploadShown();
    // GL: frees the renderer's resources.
    void release();
    bool isInitialized() const { return m_initialized; }
    // Initialised, with a scene and a program to draw.
    bool isReady() const { return m_ready; }

    // GL (once initialised): uploads `scene` with `meshes`. Either way the
    // shipped program of `shippedProgram` may now be drawing (the new
    // scene's shading, or the old one's restored after a failure).
    struct Upload {
        Result<> result;
        std::optional<ShadingMethod> shippedProgram;
    };
    Upload upload(const Scene &scene, SceneMeshes &&meshes);
    // Before GL is up: keeps `meshes` for initialize(); fails when one of
    // `scene`'s meshes is missing, so that the scene cannot fail later.
    Result<> keepUntilInitialized(const Scene &scene, SceneMeshes &&meshes);
    // After upload() or keepUntilInitialized(): `scene` is the one shown.
    void show(const Scene &scene);

    QSet<QString> loadedKeys() const;
    const QHash<QString, SceneMeshes::Entry> &meshInfo() const;

    // The scene as loaded; its camera is the orbit's original.
    const Scene &scene() const { return m_scene; }
    // The scene with the orbited camera (see Viewport::currentScene).
    Scene currentScene() const;
    // currentScene() plus the headlight: what the renderer draws.
    Scene renderedScene() const;
    Camera cameraToSave() const;

    // The scene's camera moved back as far as a view of `pixels` needs to
    // show every object; the orbit starts there. True when the camera moved.
    bool frame(const QSize &pixels);
    // The camera is still the scene's fitted to the view: a resize fits it again.
    bool isCameraFramed() const { return m_cameraFramed; }
    // The user's moves: the camera is theirs from then on.
    OrbitCamera &orbitByUser();
    const Camera &camera() const { return m_orbit.camera(); }
    void resetCamera();
    void moveLight(int index, const glm::dvec3 &position);

    void setShading(ShadingMethod method);
    void setParameters(const Scene &scene);
    void setBindings(const ExplicitBindings &bindings);
    void setHeadlight(bool on);
    bool headlight() const { return m_headlight; }
    // Parameters (camera, lights, ...) changed: sent before the next draw.
    void markChanged() { m_parametersDirty = true; }
    // Parameters or options changed since the renderer last took them: a
    // frame drawn now on another thread (LoanFrame) would show the old ones.
    bool hasUnsentChanges() const { return m_parametersDirty; }

    const Renderer::Options &options() const { return m_options; }
    void setOptions(const Renderer::Options &options);

    // GL: the scene into the bound framebuffer; without a scene only its
    // background (false).
    bool draw(const QSize &pixels);
    // GL: draws with `options` for once (an image to export or check).
    template <typename Draw> auto drawWith(const Renderer::Options &options, Draw &&draw)
    {
        sendChangedParameters();
        m_renderer.setOptions(options);
        auto result = draw(m_renderer);
        m_renderer.setOptions(m_options);
        return result;
    }
    // GL: the current program's uniform values (empty when not ready).
    UniformSnapshot programSnapshot();
    Renderer &renderer() { return m_renderer; }
    const Renderer &renderer() const { return m_renderer; }

private:
    void sendChangedParameters();

    Renderer m_renderer;
    Renderer::Options m_options{.drawLightMarkers = true};
    Scene m_scene;
    // Meshes of m_scene loaded before GL was up; initialize() uploads them.
    std::optional<SceneMeshes> m_pendingMeshes;
    OrbitCamera m_orbit;
    bool m_cameraFramed = true;
    bool m_initialized = false;    // the renderer holds GL resources
    bool m_ready = false;          // ... and a scene and program to draw
    bool m_parametersDirty = true; // changed since the renderer last saw them
    bool m_headlight = false;
};

} // namespace phonglab
