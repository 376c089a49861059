#pragma once
#include "core/MeshData.h"
#include "core/Result.h"

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLVertexArrayObject>

namespace phonglab {

// A mesh on the GPU: one VAO over an interleaved VBO (position, normal;
// attribute locations 0 and 1) and a 32-bit index buffer, held by Qt's own
// owners. On demand also its face layout (FaceLayout.h: position, face
// normal, face centroid at locations 0, 1, 2), built from the buffers read
// back, for flat shading. Needs its context current for upload/draw/destroy: a VAO, unlike
// the buffers, belongs to the one context that made it, and Qt's VAO, when
// destroyed without that context current, makes it current itself, which
// aborts while the context is lent to another thread.
class GpuMesh : protected QOpenGLExtraFunctions
{
public:
    static constexpr GLuint kPositionLocation = 0;
    static constexpr GLuint kNormalLocation = 1;
    static constexpr GLuint kFacePointLocation = 2; // the face layout only

    GpuMesh() = default;
    GpuMesh(const GpuMesh &) = delete;
    GpuMesh &operator=(const GpuMesh &) = delete;

    // Fails (and holds nothing) when the driver cannot make the objects.
    Result<> upload(const MeshData &mesh);
    void draw();
    void destroy();

    // Builds the face layout from the uploaded buffers if it is not there
    // yet. Fails (and draws nothing with faces) when the driver cannot read
    // the buffers back or make the objects.
    Result<> prepareFaceLayout();
    bool hasFaceLayout() const { return m_faces.vao.isCreated(); }
    // Draws the face layout; nothing before prepareFaceLayout() succeeded.
    void drawFaces();

    bool isValid() const { return m_shared.vao.isCreated(); }
    GLsizei indexCount() const { return m_indexCount; }

private:
    bool m_initialized = false;
    struct Buffers {
        QOpenGLVertexArrayObject vao;
        QOpenGLBuffer vbo{QOpenGLBuffer::VertexBuffer};
        QOpenGLBuffer ibo{QOpenGLBuffer::IndexBuffer};
    };
    // `attributes` vec3s per vertex, interleaved, at locations 0, 1, ...
    Result<> fill(Buffers &buffers, const std::vector<float> &vertices, int attributes,
                  const std::vector<std::uint32_t> &indices);
    void draw(Buffers &buffers);
    static void destroy(Buffers &buffers);

    Buffers m_shared; // position, normal
    Buffers m_faces;  // FaceLayout: position, face normal, face centroid
    GLsizei m_indexCount = 0;
    std::size_t m_vertexCount = 0;
};

} // namespace phonglab
