#pragma once
#include "MeshLoader.h"

#include <QByteArray>
#include <QIODevice>
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
    static void write(const QString &file, const NormalOptions &normals,
                      const MeshLoadResult &result);

    static QString entryPath(const QString &file, const NormalOptions &normals);
    // What an entry for `file` as it is now, loaded with `normals`, is keyed by.
    static QByteArray sourceKey(const QString &file, const NormalOptions &normals);

    // The entry format on any device: the import child hands its result
    // back in it. decode() refuses (nullopt) a wrong magic, version or key
    // (no key given: any), a count that cannot fit in what is left, a
    // truncated array and indices out of range; it never trusts a size
    // before checking it against the bytes that are there.
    static std::optional<MeshLoadResult> decode(QIODevice &in,
                                                const std::optional<QByteArray> &expectedKey);
    static bool encode(QIODevice &out, const QByteArray &key, const MeshLoadResult &result);
    // Moves an entry written elsewhere (the import child's answer) into the
    // cache under `file`'s key; removes it when the cache is off.
    static void adopt(const QString &entryFile, const QString &file, const NormalOptions &normals);
};

} // namespace phonglab
