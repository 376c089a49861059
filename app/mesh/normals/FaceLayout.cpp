#include "FaceLayout.h"

#include "core/reference/FaceGeometry.h"

#include <algorithm>
#include <array>

namespace phonglab {

namespace {

void appendVertex(FaceLayout &layout, const glm::vec3 &position)
{
    layout.vertices.insert(layout.vertices.end(), {position.x, position.y, position.z});
    layout.vertices.insert(layout.vertices.end(), FaceLayout::kFloatsPerVertex - 3, 0.0f);
}

void setFace(FaceLayout &layout, std::uint32_t vertex, const FaceGeometry &face)
{
    float *out = layout.vertices.data() + std::size_t(vertex) * FaceLayout::kFloatsPerVertex;
    const glm::vec3 n(face.normal);
    const glm::vec3 c(face.centroid);
    std::array values{n.x, n.y, n.z, c.x, c.y, c.z};
    std::copy(values.begin(), values.end(), out + 3);
}

} // namespace

FaceLayout buildFaceLayout(const MeshData &mesh)
{
    FaceLayout layout;
    const std::size_t triangles = mesh.triangleCount();
    layout.vertices.reserve((mesh.positions.size() + triangles / 2) * FaceLayout::kFloatsPerVertex);
    for (const glm::vec3 &p : mesh.positions)
        appendVertex(layout, p);
    layout.indices.reserve(mesh.indices.size());

    std::vector<bool> provokes(mesh.positions.size(), false);
    for (std::size_t t = 0; t < triangles; ++t) {
        std::array<std::uint32_t, 3> corner{mesh.indices[3 * t], mesh.indices[3 * t + 1],
                                            mesh.indices[3 * t + 2]};
        // Prefer the corner that is already last, so an untouched triangle
        // keeps its index order; a rotation keeps the winding either way.
        int chosen = -1;
        for (int k : {2, 0, 1})
            if (!provokes[corner[std::size_t(k)]]) {
                chosen = k;
                break;
            }
        if (chosen < 0) {
            const std::uint32_t copy = std::uint32_t(layout.vertexCount());
            appendVertex(layout, mesh.positions[corner[2]]);
            provokes.push_back(false);
            corner[2] = copy;
            chosen = 2;
        }
        std::rotate(corner.begin(), corner.begin() + (chosen + 1) % 3, corner.end());
        provokes[corner[2]] = true;
        setFace(layout, corner[2], faceGeometry(mesh, t));
        layout.indices.insert(layout.indices.end(), corner.begin(), corner.end());
    }
    return layout;
}

} // namespace phonglab
