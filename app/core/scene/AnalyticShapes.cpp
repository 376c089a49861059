#include "AnalyticShapes.h"

namespace phonglab {

std::optional<AnalyticShape> analyticShapeFor(const QString &spec)
{
    if (spec == QLatin1String("builtin:sphere"))
        return AnalyticShape::Sphere;
    if (spec == QLatin1String("builtin:torus"))
        return AnalyticShape::Torus;
    if (spec == QLatin1String("builtin:cube"))
        return AnalyticShape::Box;
    return std::nullopt;
}

QStringList builtinMeshSpecs()
{
    return {QStringLiteral("builtin:sphere"), QStringLiteral("builtin:torus"),
            QStringLiteral("builtin:cube")};
}

} // namespace phonglab
