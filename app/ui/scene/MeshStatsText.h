#pragma once
#include "mesh/loading/MeshLoader.h"

#include <QString>

namespace phonglab {

// How the Scene dock words a mesh's statistics.

// "from file", "computed (flat)", "computed (angle, crease 30°)"; builtin
// shapes: "analytic (exact)".
QString normalsDescription(const MeshStats &stats, bool builtin);
// "(-1, -0.5, -1) to (1, 0.5, 1)"
QString boundsDescription(const MeshStats &stats);
QString surfaceDescription(const MeshStats &stats);
QString countText(qint64 count); // with the locale's digit grouping
// An object's level of detail: "25 %: 3,412 of 13,650 triangles"; empty at detail 1.
QString detailDescription(const MeshStats &stats);

} // namespace phonglab
