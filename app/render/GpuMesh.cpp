#include "GpuMesh.h"

#include <vector>

namespace phonglab {

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

    if (!m_vao.create() || !m_vbo.create() || !m_ibo.create()) {
        destroy();
        return fail(QStringLiteral("the driver cannot create a vertex array or buffer"));
    }
    m_vao.bind();
    m_vbo.bind();
    // glBufferData rather than allocate(), whose int size stops at 2 GiB.
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)),
                 interleaved.data(), GL_STATIC_DRAW);
    m_ibo.bind(); // recorded in the VAO
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);

    const GLsizei stride = 6 * sizeof(float);
    glEnableVertexAttribArray(kPositionLocation);
    glVertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(kNormalLocation);
    glVertexAttribPointer(kNormalLocation, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void *>(3 * sizeof(float)));

    m_vao.release(); // the VAO keeps the element buffer binding
    m_vbo.release();
    m_indexCount = GLsizei(mesh.indices.size());
    return {};
}

void GpuMesh::draw()
{
    if (!m_vao.isCreated())
        return;
    m_vao.bind();
    glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    m_vao.release();
}

void GpuMesh::destroy()
{
    if (!m_initialized)
        return;
    m_ibo.destroy();
    m_vbo.destroy();
    m_vao.destroy();
    m_indexCount = 0;
}

} // namespace phonglab
