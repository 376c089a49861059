#pragma once
#include "core/MeshData.h"

#include <QOpenGLExtraFunctions>

namespace phonglab {

// A mesh on the GPU: one VAO over an interleaved VBO (position, normal;
// attribute locations 0 and 1) and a 32-bit index buffer. Needs a current
// context for upload/draw/destroy.
class GpuMesh : protected QOpenGLExtraFunctions
{
public:
    static constexpr GLuint kPositionLocation = 0;
    static constexpr GLuint kNormalLocation = 1;

    GpuMesh() = default;
    GpuMesh(const GpuMesh &) = delete;
    GpuMesh &operator=(const GpuMesh &) = delete;

    void upload(const MeshData &mesh);
    void draw();
    void destroy();

    bool isValid() const { return m_vao != 0; }
    GLsizei indexCount() const { return m_indexCount; }

private:
    bool m_initialized = false;
    GLuint m_vao = 0;
    GLuint m_vbo = 0;
    GLuint m_ibo = 0;
    GLsizei m_indexCount = 0;
};

} // namespace phonglab
