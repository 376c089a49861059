#pragma once
#include "core/support/Result.h"
#include "render/gl/GpuMesh.h"

#include <QOpenGLExtraFunctions>
#include <memory>

class QOpenGLFramebufferObject;

namespace phonglab {

// Draws a new program once into a few pixels so that the driver's draw-time
// work lands here instead of on the first frame the viewport draws: Mesa's
// llvmpipe JIT-compiles shader variants for the framebuffer and pipeline
// state on the first draw (80–150 ms for Phong). The target must be what
// Renderer draws into (the same colour and depth formats and sample count,
// depth test, the mesh vertex layout), because a variant is only reused for
// the same state: in the viewport's lent context that is its window's own
// framebuffer (Target::Surface); elsewhere a framebuffer object of RGBA8 and
// depth-stencil with the viewport's samples. Where the variant is kept
// depends on the driver: drivers with shareable shaders keep it with the
// program (any context of the share group benefits), llvmpipe keeps it per
// context, so there the warming must happen in the viewport's own context
// (LentContext). Needs its context current for every call.
class WarmUpDraw : protected QOpenGLExtraFunctions
{
public:
    WarmUpDraw();
    ~WarmUpDraw();
    WarmUpDraw(const WarmUpDraw &) = delete;
    WarmUpDraw &operator=(const WarmUpDraw &) = delete;

    // Where warm() draws: a framebuffer object of its own with `samples`,
    // or the framebuffer of the surface the context is current on (a corner
    // of the window's back buffer, which its next frame clears and redraws).
    enum class Target {
        OwnFramebuffer,
        Surface
    };
    Result<> create(Target target, int samples);
    bool isCreated() const { return m_mesh.isValid(); }
    void destroy();
    // One draw, then glFinish: when it returns, the program has run.
    void warm(GLuint program);

private:
    std::unique_ptr<QOpenGLFramebufferObject> m_fbo;
    GpuMesh m_mesh;
};

} // namespace phonglab
