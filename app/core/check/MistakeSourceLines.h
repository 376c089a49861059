#pragma once
#include "core/reference/ShaderMistake.h"

#include <QString>
#include <vector>

namespace phonglab {

// Where in the user's shaders a classic mistake most likely sits: the lines
// computing the term it breaks (the line with `reflect(`, the normal's
// transform, the definition of V, ...). Found by the patterns a student
// writes, not by parsing GLSL: a hint for the reader, never a proof.

struct ShaderStageText {
    QString path; // as the user named it
    QString text;
    bool vertex = false;
};

struct SourceLine {
    QString file;
    int line = 0; // 1-based, in the user's file
    QString text; // trimmed
};

// At most a few lines per stage, in file order; empty when no line looks
// like the term's.
std::vector<SourceLine> mistakeSourceLines(ShaderMistake mistake,
                                           const std::vector<ShaderStageText> &stages);

} // namespace phonglab
