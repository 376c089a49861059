#include "FaceGeometry.h"

namespace phonglab {

FaceGeometry faceGeometry(const MeshData &mesh, std::size_t triangle)
{
    const std::size_t base = 3 * triangle;
    glm::dvec3 p[3];
    glm::dvec3 vertexNormals(0.0);
    for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t v = mesh.indices[base + k];
        p[k] = glm::dvec3(mesh.positions[v]);
        vertexNormals += glm::dvec3(mesh.normals[v]);
    }
    FaceGeometry face;
    face.centroid = (p[0] + p[1] + p[2]) / 3.0;
    const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    face.normal = glm::dot(n, n) > 0.0 ? n : vertexNormals;
    return face;
}

} // namespace phonglab
