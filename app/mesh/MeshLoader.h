#pragma once
#include "MeshData.h"

#include <QString>
#include <QStringList>
#include <optional>

namespace phonglab {

struct MeshLoadResult {
    std::optional<MeshData> mesh;
    QString error;          // set when nothing was loaded
    QStringList warnings;   // every repair made while loading

    bool ok() const { return mesh.has_value(); }
};

// Loads what a scene's "mesh" names (already resolved against the scene's
// folder): a builtin shape or a mesh file.
MeshLoadResult loadMesh(const QString &spec);

} // namespace phonglab
