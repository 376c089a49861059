#pragma once
#include <QString>
#include <QStringList>

#include <optional>

namespace phonglab {

// The two programmable stages a PhongLab program is written in: one editor
// tab, one file and one compile each.
enum class ShaderStage {
    Vertex,
    Fragment
};

QString stageName(ShaderStage stage);   // "vertex", "fragment"
QString stageSuffix(ShaderStage stage); // ".vert", ".frag"

// A shader file's stage by its name's suffix, in any case: .vert .vs .vsh
// vertex, .frag .fs .fsh fragment; nullopt for .glsl (either stage: its
// text tells) and for anything else.
std::optional<ShaderStage> stageOfSuffix(const QString &path);
// Every suffix a shader file has, lower case and without the dot: the
// stages' and "glsl". The one list the editor, the dialogs, grade and the
// project reader share.
const QStringList &shaderFileSuffixes();
bool hasShaderFileSuffix(const QString &path);
// "*.vert *.frag *.vs *.fs *.vsh *.fsh *.glsl", for a file dialog's filter.
QString shaderFilePatterns();

} // namespace phonglab
