#pragma once
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <string>

namespace phonglab {

enum class MeshFileFormat {
    Obj,
    Ply,
    Off,
    Stl,
    Om
};

// Larger files are refused before anything is read: a mesh this big would
// not fit the GPU buffers anyway, and every reader holds the whole file.
inline constexpr qint64 kMaxMeshFileBytes = qint64(2) << 30;

// What the checks learnt about a file before any parser touched it.
// Messages do not repeat the path; the caller adds it.
struct MeshFilePrecheck {
    MeshFileFormat format = MeshFileFormat::Obj;
    QString error;        // set when the file must not be parsed
    QStringList warnings; // harmless oddities (trailing bytes, ...)
    qint64 fileSize = 0;
    bool binary = false;          // binary PLY, STL or OFF (OM is always binary)
    quint64 declaredVertices = 0; // from the header (PLY, OFF, OM); 0 where the format has none
    quint64 declaredFaces = 0; // from the header (PLY, OFF, OM, binary STL) or counted (ascii STL)
    // A cleaned copy of the file for the reader, which cannot cope with what
    // was cleaned: OFF comments, counts on the header line, stray face
    // values; binary STL triangles with NaN or infinite corners (OpenMesh
    // merges STL corners in a std::map, where NaN matches any key). Empty
    // when the file can be read as it is.
    std::string rewritten;

    bool ok() const { return error.isEmpty(); }
};

// The format a path's suffix names (case-insensitive), if we read it.
std::optional<MeshFileFormat> meshFileFormatForPath(const QString &path);
// ".obj, .ply, .off, .stl, .om", for messages.
QString supportedMeshFileSuffixes();

// Checks that run before any parser, so that no parser sees a file that
// would make it allocate what the header claims, loop on garbage or quietly
// misread: the file exists, is readable, not empty, not over
// kMaxMeshFileBytes; it starts with its format's magic (and is not some
// other known format renamed); header counts fit the file size (PLY, binary
// STL, OFF, OM); text formats hold no binary data; ascii PLY, OFF and ascii
// STL parse as numbers where numbers belong (errors name the line); binary
// PLY is walked element by element so a truncated file is caught.
MeshFilePrecheck precheckMeshFile(const QString &path, MeshFileFormat format);

// Reads a whole file into `bytes` in large chunks, reporting the fraction read
// to `progress` after each (returning false stops with error "cancelled").
bool readWholeFile(const QString &path, std::string &bytes, QString &error,
                   const std::function<bool(double)> &progress = {});

} // namespace phonglab
