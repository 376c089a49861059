#pragma once
#include "ProgramFindings.h"
#include "core/scene/Scene.h"
#include "core/support/Result.h"
#include "mesh/loading/SceneMeshes.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/draw/Renderer.h"
#include "render/program/ShaderSource.h"
#include "render/program/UniformSnapshot.h"

#include <QImage>
#include <QSize>
#include <functional>
#include <memory>
#include <optional>

class QOffscreenSurface;

namespace phonglab {

// Everything a frame of the window is made of, so that it can be drawn again
// elsewhere: the scene, the program's sources and values, the options.
struct FrameRecipe {
    Scene scene;                         // as drawn (the headlight included)
    std::optional<StageSources> sources; // the program; none: the shipped one of scene.shading
    UniformSnapshot uniforms;            // the program's values (the user's own uniforms)
    Renderer::Options options;           // light markers are never drawn
    QSize size;                          // device pixels
};

// The live check's copy of the window's frame, drawn in a
// context of its own on the checker's thread, into a single-sampled target.
// Single-sampled because the exact image is point-sampled: the window's 4
// samples blend every silhouette with the background and cost a correct
// shader its ✓ (57 dB at first launch). On a thread of its own because
// drawing the scene again on the GUI thread stalled typing (49 ms at p95).
// Keeps the meshes and the program between frames: after an edit only the
// program is built again, after an orbit nothing but the draw is done.
// Every call on the one thread that made it, which keeps its context.
class FrameRedraw
{
public:
    FrameRedraw() = default;
    ~FrameRedraw() { destroy(); }
    FrameRedraw(const FrameRedraw &) = delete;
    FrameRedraw &operator=(const FrameRedraw &) = delete;

    // Before meshes go to the GPU (which frees their CPU copies): another
    // user of the same meshes (the exact image) can keep them.
    using MeshesLoaded = std::function<void(const SceneMeshes &)>;
    // Draws `recipe` on `surface` (made on the GUI thread, of
    // phonglabSurfaceFormat(0); it must outlive this). keepGoing() false
    // cancels a mesh load. The image is RGB888; the failure says why.
    Result<QImage> draw(const FrameRecipe &recipe, QOffscreenSurface *surface,
                        const std::function<bool()> &keepGoing, const MeshesLoaded &meshesLoaded);
    // The program the last draw() used, for what it bound
    // (findProgramFindings()); only after a draw that succeeded.
    ShaderProgram &program() { return m_offscreen->renderer().program(); }
    // The last drawn program again as its stages declare their precision,
    // where they declare a lower one and `checked` was checked at highp:
    // measurePrecision() with the recipe's values. The next draw() builds
    // the checked program again.
    PrecisionFinding measurePrecision(const FrameRecipe &recipe,
                                      const std::vector<ShaderStageText> &stages,
                                      const Scene &checked, const QImage &checkedImage);
    // Frees the context and what it holds; on the drawing thread.
    void destroy();

private:
    Result<> useScene(const Scene &scene, const std::function<bool()> &keepGoing,
                      const MeshesLoaded &meshesLoaded);
    Result<> useProgram(const FrameRecipe &recipe);

    std::unique_ptr<OffscreenRenderer> m_offscreen;
    std::optional<Scene> m_meshesOf; // the scene whose meshes are uploaded
    // What the program was built from: sources (or none), shading, bindings.
    std::optional<std::tuple<std::optional<StageSources>, ShadingMethod, ExplicitBindings>>
        m_programOf;
};

} // namespace phonglab
