#pragma once
#include "core/scene/MeshData.h"
#include "core/scene/NormalOptions.h"
#include "mesh/import/MeshStats.h"
#include "mesh/import/PolygonMesh.h"

#include <QString>
#include <QStringList>
#include <glm/glm.hpp>

namespace phonglab {

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
    MeshStats stats; // what the builder knows of it
    QStringList warnings;
    QString error;
    bool ok() const { return error.isEmpty(); }
};
BuiltMesh buildMeshData(const PolygonMesh &mesh, const NormalOptions &options);

} // namespace phonglab
