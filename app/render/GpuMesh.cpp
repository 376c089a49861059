#include "GpuMesh.h"

#include <vector>

namespace phonglab {

void GpuMesh::upload(const MeshData &mesh)
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

    glGenVertexArrays(1, &m_vao);
    glBindVertexArray(m_vao);

    glGenBuffers(1, &m_vbo);
    glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)), interleaved.data(), GL_STATIC_DRAW);

    glGenBuffers(1, &m_ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data(),
                 GL_STATIC_DRAW);

    const GLsizei stride = 6 * sizeof(float);
    glEnableVertexAttribArray(kPositionLocation);
    glVertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(kNormalLocation);
    glVertexAttribPointer(kNormalLocation, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void *>(3 * sizeof(float)));

    glBindVertexArray(0); // the VAO keeps the element buffer binding
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    m_indexCount = GLsizei(mesh.indices.size());
}

void GpuMesh::draw()
{
    if (!m_vao)
        return;
    glBindVertexArray(m_vao);
    glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

void GpuMesh::destroy()
{
    if (!m_initialized)
        return;
    if (m_ibo)
        glDeleteBuffers(1, &m_ibo);
    if (m_vbo)
        glDeleteBuffers(1, &m_vbo);
    if (m_vao)
        glDeleteVertexArrays(1, &m_vao);
    m_vao = m_vbo = m_ibo = 0;
    m_indexCount = 0;
}

} // namespace phonglab
