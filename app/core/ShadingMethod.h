#pragma once
#include <QString>
#include <QStringList>
#include <optional>

namespace phonglab {

// The ways PhongLab can shade a surface. Each method names the shader pair
// shaders/<name>.vert + shaders/<name>.frag. New methods (flat, Gouraud,
// Blinn-Phong) are added here and as shader files; nothing else changes.
enum class ShadingMethod {
    Phong,
};

QString shadingName(ShadingMethod method);
std::optional<ShadingMethod> shadingFromName(const QString &name);
QStringList shadingNames();

} // namespace phonglab
