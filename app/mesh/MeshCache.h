#pragma once
#include "MeshLoader.h"

#include <QString>
#include <optional>

namespace phonglab {

// A binary cache of loaded meshes, so re-opening a file that has not changed
// skips parsing, repair, triangulation and normals: one read of the arrays
// the GPU gets. Keyed by the file's absolute path, size, modification time
// and the normal options; a stale, truncated or foreign cache file is
// ignored (and removed), never trusted.
//
// Folder: $PHONGLAB_CACHE_DIR, else the user's cache folder + /phonglab/meshes.
// PHONGLAB_NO_MESH_CACHE=1 turns it off.
class MeshCache
{
public:
    static bool enabled();
    static QString directory();

    static std::optional<MeshLoadResult> read(const QString &file, const NormalOptions &normals);
    // Writes atomically; failures are silent (the cache is an optimisation).
    static void write(const QString &file, const NormalOptions &normals, const MeshLoadResult &result);

    static QString entryPath(const QString &file, const NormalOptions &normals);
};

} // namespace phonglab
