#pragma once
#include "core/scene/NormalOptions.h"

#include <QtGlobal>
#include <glm/glm.hpp>

#include <optional>

namespace phonglab {

// What loading a mesh found out, for the Scene dock and `phonglab mesh-info`.
// buildMeshData() fills what it knows (sizes, normals, bounds); loadMesh()
// the rest (faces, crease, closed, time, cache).
struct MeshStats {
    qint64 fileVertices = 0; // positions the file gave (after repair)
    qint64 fileFaces = 0;    // polygons the file gave (after repair)
    qint64 vertices = 0;     // GPU vertices (after splitting)
    qint64 triangles = 0;
    qint64 splitVertices = 0; // GPU vertices beyond one per position
    bool normalsFromFile = false;
    NormalMethod normalMethod = NormalMethod::Auto; // the method actually used
    std::optional<double> creaseAngleDeg;
    glm::vec3 boundsMin{0.0f};
    glm::vec3 boundsMax{0.0f};
    bool closed = false;    // every edge has exactly two faces (safe to cull back faces)
    bool fromCache = false; // read back from MeshCache, not parsed
    double loadMs = 0.0;
    // A scene object's "detail" (SceneMeshes): the fraction asked for and the
    // triangles of the full mesh; vertices, triangles, bounds and closed then
    // describe the reduced mesh that is drawn. Not stored in MeshCache,
    // which keeps the full mesh.
    double detail = 1.0;
    qint64 fullTriangles = 0; // set only when detail != 1
};

} // namespace phonglab
