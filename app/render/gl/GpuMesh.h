#pragma once
#include "core/scene/MeshData.h"
#include "core/support/Result.h"
#include "mesh/detail/DetailLevels.h"

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLVertexArrayObject>
#include <memory>
#include <vector>

namespace phonglab {

// A mesh on the GPU: one VAO over an interleaved VBO (position, normal;
// attribute locations 0 and 1) and a 32-bit index buffer, held by Qt's own
// owners. On demand also its face layout (FaceLayout.h: position, face
// normal, face centroid at locations 0, 1, 2), built from the buffers read
// back, for flat shading. With levels of detail (DetailLevels.h), the index
// buffer holds every level one after the other, level 0 (the full mesh)
// first; a level is a range of it, drawn over the same vertices. Needs its context current for upload/draw/destroy: a VAO, unlike
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
    // `levels`, when given, must be levels of `mesh` (levels[0] its indices).
    Result<> upload(const MeshData &mesh, const DetailLevels *levels = nullptr);
    void draw(int level = 0);
    void destroy();

    // Builds the face layout of `level` from the uploaded buffers if it is
    // not there yet. Fails (and draws nothing with faces) when the driver
    // cannot read the buffers back or make the objects.
    Result<> prepareFaceLayout(int level = 0);
    // Draws the face layout; nothing before prepareFaceLayout() succeeded.
    void drawFaces(int level = 0);

    bool isValid() const { return m_shared.vao.isCreated(); }
    GLsizei indexCount(int level = 0) const { return m_levels[std::size_t(level)].count; }
    // 1 without levels of detail.
    int levelCount() const { return int(m_levels.size()); }
    // Object units (DetailLevel::error); 0 for level 0.
    double levelError(int level) const { return m_levels[std::size_t(level)].error; }
    // Radians (DetailLevel::normalDeviation); 0 for level 0.
    double levelNormalDeviation(int level) const
    {
        return m_levels[std::size_t(level)].normalDeviation;
    }

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
    static void destroy(Buffers &buffers);

    struct Level {
        GLsizei first = 0; // into the index buffer, in indices
        GLsizei count = 0;
        double error = 0.0;
        double normalDeviation = 0.0;
        std::unique_ptr<Buffers> faces; // FaceLayout: position, face normal, face centroid
    };

    Buffers m_shared;                                    // position, normal
    std::vector<Level> m_levels = std::vector<Level>(1); // level 0: the whole index buffer
    std::size_t m_vertexCount = 0;
};

} // namespace phonglab
