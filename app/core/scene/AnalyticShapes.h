#pragma once
#include <QString>
#include <QStringList>
#include <optional>

namespace phonglab {

// The analytic surfaces behind the builtin meshes: what "builtin:sphere",
// "builtin:torus" and "builtin:cube" are exactly. The reference ray-casts
// these; mesh/import/BuiltinMeshes tessellates them for the GPU.
enum class AnalyticShape {
    Sphere, // radius 1 at the origin
    Torus,  // around the Y axis, ring radius kTorusMajorRadius, tube radius kTorusMinorRadius
    Box,    // [-1, 1]³
};

inline constexpr double kTorusMajorRadius = 1.0;
inline constexpr double kTorusMinorRadius = 0.4;

// The shape a builtin mesh spec names; nullopt for anything else.
std::optional<AnalyticShape> analyticShapeFor(const QString &spec);
// Every builtin mesh spec: "builtin:sphere", "builtin:torus", "builtin:cube".
QStringList builtinMeshSpecs();

} // namespace phonglab
