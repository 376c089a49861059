#pragma once
#include "core/scene/MeshData.h"

#include <cstdint>
#include <vector>

namespace phonglab {

// A mesh laid out for flat shading (shaders/flat.vert): the same triangles,
// each rotated (which keeps its winding) so that its last vertex, GL's
// provoking vertex, provokes no other triangle, and that vertex carries the
// face's normal and centroid (FaceGeometry.h) for the one evaluation of the
// equation per face. Where all three corners of a triangle already provoke
// others, its last corner is copied into a new vertex. A closed mesh has
// about twice as many triangles as vertices, so about half of them need a
// copy: far less than three vertices per triangle.
//
// Per vertex: position, face normal, face centroid (object coordinates, 9
// floats). A vertex that provokes nothing carries zeros there; no fragment
// ever reads them.
struct FaceLayout {
    static constexpr int kFloatsPerVertex = 9;
    std::vector<float> vertices;
    std::vector<std::uint32_t> indices;

    std::size_t vertexCount() const { return vertices.size() / kFloatsPerVertex; }
};

// `mesh` must be valid (MeshData::isValid()).
FaceLayout buildFaceLayout(const MeshData &mesh);

} // namespace phonglab
