#pragma once
#include "core/MeshData.h"
#include "core/NormalOptions.h"

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>

namespace phonglab {

// What loading a mesh found out, for the Scene dock and `phonglab mesh-info`.
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
