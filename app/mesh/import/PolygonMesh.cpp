#include "PolygonMesh.h"

namespace phonglab {

void PolygonMesh::reserve(std::size_t vertices, std::size_t faces, std::size_t corners)
{
    positions.reserve(vertices);
    faceStart.reserve(faces + 1);
    cornerPosition.reserve(corners);
}

} // namespace phonglab
