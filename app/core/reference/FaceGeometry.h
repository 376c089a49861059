#pragma once
#include "core/scene/MeshData.h"

#include <glm/glm.hpp>

#include <cstddef>

namespace phonglab {

// What flat shading evaluates the illumination equation with, for one
// triangle of a mesh (object coordinates): the centroid as the face's
// representative point, and the geometric normal of the triangle's plane,
// oriented by its winding (counter-clockwise is the front, as GL culls).
// A degenerate triangle, whose plane is undefined, takes the sum of its
// three vertex normals instead; it covers no pixel either way.
struct FaceGeometry {
    glm::dvec3 centroid{0.0};
    glm::dvec3 normal{0.0, 0.0, 1.0}; // not normalised: the normal matrix comes first
};

FaceGeometry faceGeometry(const MeshData &mesh, std::size_t triangle);

} // namespace phonglab
