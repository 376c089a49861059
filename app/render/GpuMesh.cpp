#include "GpuMesh.h"

#include "mesh/FaceLayout.h"

#include <limits>
#include <vector>

namespace phonglab {

namespace {
constexpr int kSharedAttributes = 2; // position, normal
}

Result<> GpuMesh::upload(const MeshData &mesh)
{
    if (!m_initialized) {
        initializeOpenGLFunctions();
        m_initialized = true;
    }
    destroy();

    std::vector<float> interleaved;
    interleaved.reserve(mesh.positions.size() * 6);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 &p = mesh.positions[i];
        const glm::vec3 &n = mesh.normals[i];
        interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
    }
    if (Result<> filled = fill(m_shared, interleaved, kSharedAttributes, mesh.indices); !filled) {
        destroy();
        return filled;
    }
    m_indexCount = GLsizei(mesh.indices.size());
    m_vertexCount = mesh.positions.size();
    return {};
}

Result<> GpuMesh::fill(Buffers &buffers, const std::vector<float> &vertices, int attributes,
                       const std::vector<std::uint32_t> &indices)
{
    if (!buffers.vao.create() || !buffers.vbo.create() || !buffers.ibo.create())
        return fail(QStringLiteral("the driver cannot create a vertex array or buffer"));
    buffers.vao.bind();
    buffers.vbo.bind();
    // glBufferData rather than allocate(), whose int size stops at 2 GiB.
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(),
                 GL_STATIC_DRAW);
    buffers.ibo.bind(); // recorded in the VAO
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)),
                 indices.data(), GL_STATIC_DRAW);

    const GLsizei stride = GLsizei(3 * attributes * sizeof(float));
    for (int a = 0; a < attributes; ++a) {
        glEnableVertexAttribArray(GLuint(a));
        glVertexAttribPointer(GLuint(a), 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void *>(3 * a * sizeof(float)));
    }
    buffers.vao.release(); // the VAO keeps the element buffer binding
    buffers.vbo.release();
    return {};
}

Result<> GpuMesh::prepareFaceLayout()
{
    if (hasFaceLayout())
        return {};
    if (!isValid())
        return fail(QStringLiteral("no mesh uploaded"));
    // QOpenGLBuffer::read() counts bytes in an int.
    const std::size_t vertexBytes = m_vertexCount * kSharedAttributes * 3 * sizeof(float);
    const std::size_t indexBytes = std::size_t(m_indexCount) * sizeof(std::uint32_t);
    if (vertexBytes > std::size_t(std::numeric_limits<int>::max())
        || indexBytes > std::size_t(std::numeric_limits<int>::max()))
        return fail(QStringLiteral("the mesh is too large to read back for flat shading"));

    // The CPU copy is gone once uploaded (Renderer::setScene): read it back.
    std::vector<float> interleaved(m_vertexCount * kSharedAttributes * 3);
    MeshData mesh;
    mesh.indices.resize(std::size_t(m_indexCount));
    m_shared.vbo.bind();
    const bool readVertices = m_shared.vbo.read(0, interleaved.data(), int(vertexBytes));
    m_shared.vbo.release();
    m_shared.vao.bind(); // the element buffer binding is the VAO's
    m_shared.ibo.bind();
    const bool readIndices = m_shared.ibo.read(0, mesh.indices.data(), int(indexBytes));
    m_shared.vao.release();
    if (!readVertices || !readIndices)
        return fail(QStringLiteral("the driver cannot read the mesh back for flat shading"));

    mesh.positions.resize(m_vertexCount);
    mesh.normals.resize(m_vertexCount);
    for (std::size_t i = 0; i < m_vertexCount; ++i) {
        const float *v = interleaved.data() + 6 * i;
        mesh.positions[i] = {v[0], v[1], v[2]};
        mesh.normals[i] = {v[3], v[4], v[5]};
    }
    const FaceLayout layout = buildFaceLayout(mesh);
    if (Result<> filled =
            fill(m_faces, layout.vertices, FaceLayout::kFloatsPerVertex / 3, layout.indices);
        !filled) {
        destroy(m_faces);
        return filled;
    }
    return {};
}

void GpuMesh::draw()
{
    draw(m_shared);
}

void GpuMesh::drawFaces()
{
    draw(m_faces);
}

void GpuMesh::draw(Buffers &buffers)
{
    if (!buffers.vao.isCreated())
        return;
    buffers.vao.bind();
    glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    buffers.vao.release();
}

void GpuMesh::destroy(Buffers &buffers)
{
    buffers.ibo.destroy();
    buffers.vbo.destroy();
    buffers.vao.destroy();
}

void GpuMesh::destroy()
{
    if (!m_initialized)
        return;
    destroy(m_faces);
    destroy(m_shared);
    m_indexCount = 0;
    m_vertexCount = 0;
}

} // namespace phonglab
