#pragma once
#include "PolygonMesh.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <optional>

namespace phonglab {

struct MeshReadResult {
    std::optional<PolygonMesh> mesh; // set when the file was read
    QString error;                   // set when nothing was read; does not repeat the path
    QStringList warnings;            // everything read differently from what the file says

    bool ok() const { return mesh.has_value(); }
};

// Reads a mesh file into a PolygonMesh as the file gives it: no repair yet
// (the caller runs repairMesh() and turns "no faces left" into an error).
// The format follows the suffix, case-insensitively: .obj (our own parser),
// .ply, .off, .stl, .om (OpenMesh's readers, after precheckMeshFile() made
// sure they will not misread or over-allocate). Never throws; a file with no
// faces is an error. `progress` gets the fraction done (0..1) now and then,
// at least every few MB for OBJ; returning false stops the read with error
// "cancelled".
MeshReadResult readMeshFile(const QString &path, const std::function<bool(double)> &progress = {});

} // namespace phonglab
