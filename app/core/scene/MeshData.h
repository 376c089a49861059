#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace phonglab {

// A triangle mesh ready for the GPU: one normal per vertex (object
// coordinates), indexed triangles with 32-bit indices.
struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;

    std::size_t triangleCount() const { return indices.size() / 3; }
    bool isValid() const;
};

} // namespace phonglab
