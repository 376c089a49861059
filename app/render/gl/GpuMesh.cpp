#include "GpuMesh.h"

#include "mesh/normals/FaceLayout.h"

#include <QCoreApplication>
#include <limits>
#include <vector>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct GpuMeshWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::GpuMesh)
};

namespace {
constexpr int kSharedAttributes = 2; // position, normal

// QOpenGLBuffer::read() counts bytes in an int.
bool fitsRead(std::size_t bytes)
{
    return bytes <= std::size_t(std::numeric_limits<int>::max());
}
} // namespace

Result<> GpuMesh::upload(const MeshData &mesh, const DetailLevels *levels)
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
    std::vector<std::uint32_t> indices = mesh.indices;
    std::vector<Level> ranges(1);
    ranges.front().count = GLsizei(mesh.indices.size());
    if (levels)
        for (std::size_t i = 1; i < levels->levels.size(); ++i) {
            const DetailLevel &level = levels->levels[i];
            Level range;
            range.first = GLsizei(indices.size());
            range.count = GLsizei(level.indices.size());
            range.error = level.error;
            range.normalDeviation = level.normalDeviation;
            indices.insert(indices.end(), level.indices.begin(), level.indices.end());
            ranges.push_back(std::move(range));
        }
    if (Result<> filled = fill(m_shared, interleaved, kSharedAttributes, indices); !filled) {
        destroy();
        return filled;
    }
    m_levels = std::move(ranges);
    m_vertexCount = mesh.positions.size();
    return {};
}

Result<> GpuMesh::fill(Buffers &buffers, const std::vector<float> &vertices, int attributes,
                       const std::vector<std::uint32_t> &indices)
{
    if (!buffers.vao.create() || !buffers.vbo.create() || !buffers.ibo.create())
        return fail(GpuMeshWords::tr("the driver cannot create a vertex array or buffer"));
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

Result<> GpuMesh::prepareFaceLayout(int level)
{
    if (!isValid())
        return fail(GpuMeshWords::tr("no mesh uploaded"));
    Level &range = m_levels[std::size_t(level)];
    if (range.faces)
        return {};
    const std::size_t vertexBytes = m_vertexCount * kSharedAttributes * 3 * sizeof(float);
    const std::size_t indexBytes = std::size_t(range.count) * sizeof(std::uint32_t);
    const std::size_t indexOffset = std::size_t(range.first) * sizeof(std::uint32_t);
    if (!fitsRead(vertexBytes) || !fitsRead(indexBytes) || !fitsRead(indexOffset))
        return fail(GpuMeshWords::tr("the mesh is too large to read back for flat shading"));

    // The CPU copy is gone once uploaded (Renderer::setScene): read it back.
    std::vector<float> interleaved(m_vertexCount * kSharedAttributes * 3);
    MeshData mesh;
    mesh.indices.resize(std::size_t(range.count));
    m_shared.vbo.bind();
    const bool readVertices = m_shared.vbo.read(0, interleaved.data(), int(vertexBytes));
    m_shared.vbo.release();
    m_shared.vao.bind(); // the element buffer binding is the VAO's
    m_shared.ibo.bind();
    const bool readIndices =
        m_shared.ibo.read(int(indexOffset), mesh.indices.data(), int(indexBytes));
    m_shared.vao.release();
    if (!readVertices || !readIndices)
        return fail(GpuMeshWords::tr("the driver cannot read the mesh back for flat shading"));

    mesh.positions.resize(m_vertexCount);
    mesh.normals.resize(m_vertexCount);
    for (std::size_t i = 0; i < m_vertexCount; ++i) {
        const float *v = interleaved.data() + 6 * i;
        mesh.positions[i] = {v[0], v[1], v[2]};
        mesh.normals[i] = {v[3], v[4], v[5]};
    }
    const FaceLayout layout = buildFaceLayout(mesh);
    auto faces = std::make_unique<Buffers>();
    if (Result<> filled =
            fill(*faces, layout.vertices, FaceLayout::kFloatsPerVertex / 3, layout.indices);
        !filled) {
        destroy(*faces);
        return filled;
    }
    range.faces = std::move(faces);
    return {};
}

void GpuMesh::draw(int level)
{
    if (!m_shared.vao.isCreated())
        return;
    const Level &range = m_levels[std::size_t(level)];
    m_shared.vao.bind();
    glDrawElements(
        GL_TRIANGLES, range.count, GL_UNSIGNED_INT,
        reinterpret_cast<const void *>(std::size_t(range.first) * sizeof(std::uint32_t)));
    m_shared.vao.release();
}

void GpuMesh::drawFaces(int level)
{
    const Level &range = m_levels[std::size_t(level)];
    if (!range.faces || !range.faces->vao.isCreated())
        return;
    range.faces->vao.bind();
    glDrawElements(GL_TRIANGLES, range.count, GL_UNSIGNED_INT, nullptr);
    range.faces->vao.release();
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
    for (Level &level : m_levels)
        if (level.faces)
            destroy(*level.faces);
    m_levels.clear();
    m_levels.emplace_back();
    destroy(m_shared);
    m_vertexCount = 0;
}

} // namespace phonglab
