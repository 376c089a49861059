#pragma once
#include "MeshFilePrecheck.h"

namespace phonglab {

// The OM part of precheckMeshFile(). OpenMesh's OM reader trusts every chunk
// header: it asserts (and aborts) on a vector dimension it does not expect,
// reads or skips whatever size a header implies, and a named custom property
// of a known type trips an assertion in a kernel with no elements, which is
// what our importer gives it. So the whole file is walked chunk by chunk
// first, with the reader's size rules: every chunk must fit the bytes left,
// have the dimensions the reader asserts, and the file must end at the end
// marker. The reader then sees only the chunks PhongLab draws (positions,
// normals, topology): when the file has others (texture coordinates,
// colours, status, custom properties), check.rewritten holds a copy without
// them, so no version's handling of those can misread the rest.
// `check` arrives with fileSize set; the function sets error or the declared
// counts, binary, warnings and rewritten.
void precheckOm(const QString &path, MeshFilePrecheck &check);

} // namespace phonglab
