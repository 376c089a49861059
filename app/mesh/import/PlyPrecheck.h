#pragma once
#include "MeshFilePrecheck.h"

namespace phonglab {

// The PLY part of precheckMeshFile(): parses the header, checks that its
// element counts fit the file, then walks a binary body element by element
// (list lengths included) or validates every ascii value, so that OpenMesh's
// reader only ever sees a file it reads to the end without misreading.
// `check` arrives with fileSize set; the function sets error or the
// declared counts and the binary flag.
void precheckPly(const QString &path, MeshFilePrecheck &check);

} // namespace phonglab
