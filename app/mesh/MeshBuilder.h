#pragma once
#include "PolygonMesh.h"
#include "core/MeshData.h"
#include "core/NormalOptions.h"

#include <QString>
#include <QStringList>
#include <glm/glm.hpp>

namespace phonglab {

// What buildMeshData made of a mesh, for the status bar and the CLI.
struct BuildStats {
    qint64 fileVertices = 0; // positions in the file
    qint64 vertices = 0;     // GPU vertices
    qint64 triangles = 0;
    qint64 splitVertices = 0; // GPU vertices − distinct positions used: the cost of hard edges
    bool normalsFromFile = false;
    // The method that produced the normals: Auto only when they came from
    // the file, AngleWeighted when Auto had to compute them.
    NormalMethod method = NormalMethod::Auto;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f}; // over the positions the GPU mesh uses
};

// Turns a repaired PolygonMesh into GPU-ready MeshData: triangulates,
// chooses normals as `options` says, and welds, giving one GPU vertex per
// distinct (position, normal) pair. Normals come from the file only for
// NormalMethod::Auto and only when every corner has one; they are used as
// written, only normalised where not unit length (zero or non-finite ones
// are replaced by computed angle-weighted normals). Every compromise is
// listed in `warnings`. On failure (no faces; more triangle corners than
// 32-bit indices reach) `mesh` is empty and `error` says why.
struct BuiltMesh {
    MeshData mesh;
    BuildStats stats;
    QStringList warnings;
    QString error;
    bool ok() const { return error.isEmpty(); }
};
BuiltMesh buildMeshData(const PolygonMesh &mesh, const NormalOptions &options);

} // namespace phonglab
