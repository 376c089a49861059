#pragma once
#include "MeshFilePrecheck.h"
#include "MeshFileReader.h"

namespace phonglab {

// Reads PLY (ascii and binary), OFF, STL (ascii and binary) and OM through
// OpenMesh's reader modules into a PolygonSoupImporter, so faces arrive as
// the file gives them. `check` is the file's passed precheck: it decides
// binary STL vs ascii (OpenMesh guesses from a leading "solid", which many
// binary exporters write), supplies a cleaned OFF text where needed, and
// its declared counts drive progress and are compared with what was read.
//
// OpenMesh's reader modules are singletons with state, so reads are
// serialised. Their console output (omerr, omlog, omout) is captured while
// reading; omerr lines become warnings (or the error, when the read fails).
// Every exception is caught, std::bad_alloc included.
MeshReadResult readWithOpenMesh(const QString &path, const MeshFilePrecheck &check,
                                const std::function<bool(double)> &progress = {});

} // namespace phonglab
