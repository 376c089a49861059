#pragma once
#include <QString>
#include <optional>
#include <vector>

namespace phonglab {

// One uniform as the shader text declares it, with the hints its trailing
// comment gives the Uniforms dock:
//   uniform float gain;          // @range 0 2 @step 0.05
//   uniform vec3 tint, glow[2];  // @color
// The annotations apply to every declarator of the line.
struct UniformDeclaration {
    QString type; // "float", "vec3", "sampler2D", ...
    QString name;
    bool isArray = false;
    int arraySize = 0; // 0: not an array, or a size given by a constant
    std::optional<double> rangeLow;
    std::optional<double> rangeHigh;
    std::optional<double> step;
    bool color = false;

    bool hasRange() const { return rangeLow && rangeHigh; }
};

// Every default-block uniform declared in `source`, in order. Text-level
// only (no preprocessor): comments are skipped, so a commented-out
// declaration is not listed; a declaration inside an #if 0 still is.
std::vector<UniformDeclaration> parseUniformDeclarations(const QString &source);

// The annotation part of a comment: "@range 0 2 @color" -> range, colour.
void parseUniformAnnotations(const QString &comment, UniformDeclaration &declaration);

} // namespace phonglab
