#pragma once
#include <QString>

namespace phonglab {

// The two programmable stages a PhongLab program is written in: one editor
// tab, one file and one compile each.
enum class ShaderStage {
    Vertex,
    Fragment
};

QString stageName(ShaderStage stage);   // "vertex", "fragment"
QString stageSuffix(ShaderStage stage); // ".vert", ".frag"

} // namespace phonglab
