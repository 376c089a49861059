#pragma once
#include "core/scene/MeshData.h"
#include "core/scene/NormalOptions.h"
#include "mesh/import/MeshStats.h"

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>

namespace phonglab {

struct MeshLoadResult {
    std::optional<MeshData> mesh;
    QString error;        // set when nothing was loaded
    QStringList warnings; // every repair made while loading
    MeshStats stats;

    bool ok() const { return mesh.has_value(); }
};

// progress(fraction) is called from the loading thread now and then;
// returning false cancels the load (error "cancelled").
using LoadProgress = std::function<bool(double)>;

// Loads what a scene's "mesh" names (already resolved against the scene's
// folder): a builtin shape or a mesh file (OBJ, PLY, OFF, STL, OM). A file
// the mesh cache does not hold yet is parsed in a child process under time
// and memory limits (MeshImportProcess), so a reader that hangs, runs out
// of memory or crashes costs an error message, never the app. Safe to call
// from any thread; touches no GL. The app, mesh-info, render and bench all
// load through here.
MeshLoadResult loadMesh(const QString &spec, const NormalOptions &normals = {},
                        const LoadProgress &progress = {});

// Parses, repairs and builds a mesh file in this process: what the import
// child runs, and what fuzzers and reader tests call directly. No cache,
// no limits: a reader bug here is this process's bug.
MeshLoadResult importMeshFile(const QString &path, const NormalOptions &normals = {},
                              const LoadProgress &progress = {});

} // namespace phonglab
