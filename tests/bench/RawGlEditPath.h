#pragma once
#include "EditSample.h"
#include "RawGlCalls.h"
#include "core/scene/MeshData.h"
#include "core/scene/Scene.h"

#include <QOpenGLContext>
#include <QSize>
#include <QWindow>

namespace phonglab::bench {

// The baseline an edit is measured against: the same steps with plain GL
// calls (glCreateShader, glCompileShader, glLinkProgram, one draw of the
// mesh with the scene's uniforms, swapBuffers), no Qt wrappers, on a context
// of its own drawing into a window of its own like the viewport's (same
// size and samples) and presenting: an edit ends when its pixel reaches the
// window, on both paths.
class RawGlEditPath
{
public:
    RawGlEditPath() = default;
    ~RawGlEditPath();
    RawGlEditPath(const RawGlEditPath &) = delete;
    RawGlEditPath &operator=(const RawGlEditPath &) = delete;

    // Scene's first object and `mesh` (its mesh) are what every edit draws.
    bool create(const QSize &size, int samples, const Scene &scene, const MeshData &mesh);
    // Builds `fragment` with the shipped Phong vertex shader and draws once.
    EditSample edit(const QByteArray &fragment);

private:
    QOpenGLContext m_context;
    QWindow m_window;
    QSize m_size;
    Scene m_scene;
    QByteArray m_vertex;
    RawMesh m_mesh;
};

} // namespace phonglab::bench
