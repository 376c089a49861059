#pragma once
#include <QString>
#include <QStringList>
#include <optional>

namespace phonglab {

// The ways PhongLab can shade a surface. Each method names the shader pair
// shaders/<name>.vert + shaders/<name>.frag; every pair reads the same
// attributes and uniforms as phong.*, so the renderer drives them all alike.
// docs/shading-methods.md says what each computes and where it breaks.
enum class ShadingMethod {
    Phong,      // "phong": the illumination equation per fragment
    BlinnPhong, // "blinn-phong": per fragment, specular from the half vector (exponent 4n)
    Gouraud,    // "gouraud": the equation per vertex, colour interpolated
    Flat,       // "flat": the equation once per face, at its centroid with its face normal
    Faceted,    // "faceted": per fragment with the geometric face normal (dFdx/dFdy)
    Normals,    // "normals": the camera-space normal as a colour, no lighting
};

QString shadingName(ShadingMethod method);
std::optional<ShadingMethod> shadingFromName(const QString &name);
QStringList shadingNames(); // in declaration order, "phong" first

} // namespace phonglab
