#pragma once
#include "core/MeshData.h"
#include "core/Result.h"

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLVertexArrayObject>

namespace phonglab {

// A mesh on the GPU: one VAO over an interleaved VBO (position, normal;
// attribute locations 0 and 1) and a 32-bit index buffer, held by Qt's own
// owners. Needs its context current for upload/draw/destroy: a VAO, unlike
// the buffers, belongs to the one context that made it, and Qt's VAO, when
// destroyed without that context current, makes it current itself, which
// aborts while the context is lent to another thread.
class GpuMesh : protected QOpenGLExtraFunctions
{
public:
    static constexpr GLuint kPositionLocation = 0;
    static constexpr GLuint kNormalLocation = 1;

    GpuMesh() = default;
    GpuMesh(const GpuMesh &) = delete;
    GpuMesh &operator=(const GpuMesh &) = delete;

    // Fails (and holds nothing) when the driver cannot make the objects.
    Result<> upload(const MeshData &mesh);
    void draw();
    void destroy();

    bool isValid() const { return m_vao.isCreated(); }
    GLsizei indexCount() const { return m_indexCount; }

private:
    bool m_initialized = false;
    QOpenGLVertexArrayObject m_vao;
    QOpenGLBuffer m_vbo{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer m_ibo{QOpenGLBuffer::IndexBuffer};
    GLsizei m_indexCount = 0;
};

} // namespace phonglab
