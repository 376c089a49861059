#pragma once
#include "MeshFileReader.h"

#include <string_view>

namespace phonglab {

// Our own OBJ parser. OpenMesh's keeps one normal per vertex, which gives a
// flat-shaded export (a different `vn` at each corner of a vertex) wrong
// normals, and it is more than ten times slower.
//
// Reads `v x y z [w]` (w and vertex colours ignored), `vn`, and `f`/`fo`
// with corners `v`, `v/vt`, `v//vn`, `v/vt/vn`, negative (relative) indices
// included; polygons stay polygons. Lines continued with a trailing `\` are
// joined; a `#` after a face's corners starts a comment; a leading UTF-8 byte
// order mark is skipped. Texture coordinates, groups, objects, smoothing groups, materials,
// lines and points are ignored; free-form curve and surface statements are
// ignored with a warning.
//
// Indices are resolved to 0-based as given; MeshRepair drops faces whose
// index is out of range. An index that cannot be resolved at all (0, or a
// relative one reaching before the first vertex) becomes 0xffffffff. A line
// that cannot be parsed is skipped and counted, except that a broken `v` or
// `vn` line still takes its index (as NaN) so the indices after it keep
// pointing where the file meant. Corners with no normal, or whose normal
// does not exist (counted), get PolygonMesh::kNoNormal; cornerNormal stays
// empty when no corner has one.
MeshReadResult parseObj(std::string_view text, const std::function<bool(double)> &progress = {});

// Reads the whole file into memory, then parseObj(). The file is assumed to
// have passed precheckMeshFile().
MeshReadResult readObjFile(const QString &path, const std::function<bool(double)> &progress = {});

} // namespace phonglab
