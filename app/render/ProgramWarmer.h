#pragma once
#include "GpuMesh.h"

#include <QOpenGLExtraFunctions>
#include <memory>

class QOpenGLFramebufferObject;

namespace phonglab {

// Draws a new program once into a tiny framebuffer so that the driver's
// draw-time work lands here instead of on the first frame the viewport draws:
// Mesa's llvmpipe JIT-compiles a shader variant for the framebuffer and
// pipeline state on the first draw (80–100 ms for Phong), and keeps it with
// the program, where any context of the share group finds it. The target
// mirrors what Renderer draws into (RGBA8, depth-stencil, the viewport's
// sample count, depth test, the mesh vertex layout), because a variant is
// only reused for the same state. Needs its context current for every call.
class ProgramWarmer : protected QOpenGLExtraFunctions
{
public:
    ProgramWarmer();
    ~ProgramWarmer();
    ProgramWarmer(const ProgramWarmer &) = delete;
    ProgramWarmer &operator=(const ProgramWarmer &) = delete;

    bool create(int samples, QString *error);
    void destroy();
    // One draw, then glFinish: when it returns, the program has run.
    void warm(GLuint program);

private:
    std::unique_ptr<QOpenGLFramebufferObject> m_fbo;
    GpuMesh m_mesh;
};

} // namespace phonglab
