#pragma once
#include "MeshData.h"

#include <QString>
#include <optional>

namespace phonglab {

// Analytic shapes tessellated with exact normals; they stand in for imported
// meshes and serve as ground truth (the CPU reference ray-casts the same
// analytic surfaces).
//
// Unit sphere: radius 1 at the origin. `slices` around Y, `stacks` pole to pole.
MeshData makeUvSphere(int slices, int stacks);

// Torus around the Y axis: ring radius `majorRadius`, tube radius `minorRadius`.
inline constexpr double kTorusMajorRadius = 1.0;
inline constexpr double kTorusMinorRadius = 0.4;
MeshData makeTorus(int ringSegments, int tubeSegments,
                   double majorRadius = kTorusMajorRadius, double minorRadius = kTorusMinorRadius);

// The box [-1, 1]³ with one flat normal per face (24 vertices, 12 triangles).
MeshData makeCube();

// "builtin:sphere" / "builtin:torus" at the default (fine) tessellation,
// "builtin:cube";
// nullopt for any other name.
std::optional<MeshData> builtinMesh(const QString &spec);
bool isBuiltinMeshSpec(const QString &spec);

} // namespace phonglab
