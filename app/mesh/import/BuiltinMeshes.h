#pragma once
#include "core/scene/AnalyticShapes.h"
#include "core/scene/MeshData.h"

#include <QString>
#include <optional>

namespace phonglab {

// Analytic shapes tessellated with exact normals; they stand in for imported
// meshes and serve as ground truth (the CPU reference ray-casts the same
// analytic surfaces).
//
// Unit sphere: radius 1 at the origin. `slices` around Y, `stacks` pole to pole.
MeshData makeUvSphere(int slices, int stacks);

// Torus around the Y axis: ring radius `majorRadius`, tube radius `minorRadius`
// (by default the analytic torus of core/AnalyticShapes.h).
MeshData makeTorus(int ringSegments, int tubeSegments, double majorRadius = kTorusMajorRadius,
                   double minorRadius = kTorusMinorRadius);

// The box [-1, 1]³ with one flat normal per face (24 vertices, 12 triangles).
MeshData makeCube();

// "builtin:sphere" / "builtin:torus" at the default (fine) tessellation,
// "builtin:cube";
// nullopt for any other name.
std::optional<MeshData> builtinMesh(const QString &spec);
bool isBuiltinMeshSpec(const QString &spec);

// Levels of detail: the sphere and torus tessellated coarser, both grid
// counts scaled by sqrt(detail) from the defaults (sphere 256×128 slices ×
// stacks, torus 192×96 ring × tube segments) so the triangle count is about
// detail × the full one, never below 6×3. The cube has one tessellation.
// detail in (0, 1]; anything else means 1.
inline constexpr int kMinBuiltinColumns = 6;
inline constexpr int kMinBuiltinRows = 3;
struct BuiltinTessellation {
    int columns = 0; // sphere: slices; torus: ring segments
    int rows = 0;    // sphere: stacks; torus: tube segments
    bool operator==(const BuiltinTessellation &) const = default;
};
std::optional<BuiltinTessellation> builtinTessellation(const QString &spec,
                                                       double detail); // sphere, torus only
std::optional<MeshData> builtinMesh(const QString &spec, double detail);
// The tessellation for labels: "32×16" (sphere, torus), "6 faces" (cube),
// empty for an unknown name.
QString builtinDetailLabel(const QString &spec, double detail);

} // namespace phonglab
