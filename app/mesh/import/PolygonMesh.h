#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace phonglab {

// A mesh as a file describes it, before any repair: polygons of any size
// whose corners index a position and, when the file has normals, a normal
// (a per-face-corner normal, as OBJ's `f v//vn` gives it; formats with
// per-vertex normals use the vertex's index for both). Readers produce this;
// MeshBuilder turns it into GPU-ready MeshData.
struct PolygonMesh {
    static constexpr std::uint32_t kNoNormal = 0xffffffffu;

    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;          // the file's normals (may be empty)
    std::vector<std::uint32_t> faceStart{0}; // face f uses corners [faceStart[f], faceStart[f+1])
    std::vector<std::uint32_t> cornerPosition;
    std::vector<std::uint32_t> cornerNormal; // parallel to cornerPosition; empty if no normals

    std::size_t faceCount() const { return faceStart.size() - 1; }
    std::size_t cornerCount(std::size_t face) const
    {
        return faceStart[face + 1] - faceStart[face];
    }
    bool hasNormals() const { return !cornerNormal.empty(); }

    void reserve(std::size_t vertices, std::size_t faces, std::size_t corners);
};

} // namespace phonglab
