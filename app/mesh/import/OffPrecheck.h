#pragma once
#include "MeshFilePrecheck.h"

#include <string_view>

namespace phonglab {

// Whether `head` starts, after blank lines and comments, with an OFF
// header keyword ([ST][C][N][4][n]OFF).
bool offHeaderAt(std::string_view head);

// The OFF part of precheckMeshFile(). OpenMesh's OFF reader takes the first
// line as the header, reads counts and values with operator>> and face
// colours from the rest of a line only under a COFF header; it knows no
// comments. So every line is validated here (errors name the line), and a
// file using what that reader cannot parse (comments, counts on the header
// line as in ModelNet's "OFF1234 5678 0", values after a face's indices
// without COFF) gets a cleaned copy in check.rewritten.
void precheckOff(const QString &path, MeshFilePrecheck &check);

} // namespace phonglab
