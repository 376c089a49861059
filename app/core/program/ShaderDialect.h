#pragma once
#include <QByteArray>
#include <QString>

namespace phonglab {

// Which GLSL a shader is written in, read from its #version line. Students of
// a WebGL course write GLSL ES: 3.00 (WebGL 2, `#version 300 es`) or 1.00
// (WebGL 1: `#version 100`, or no #version line at all, with `attribute`,
// `varying` and `gl_FragColor`). Desktop GL contexts run both where the
// driver has ARB_ES3_compatibility / ARB_ES2_compatibility (Mesa does); a
// shader with no #version line is taken as GLSL ES 1.00, since desktop GLSL
// 1.10 cannot run in a core context anyway.
enum class ShaderDialect {
    Desktop, // #version 330 core and the like
    Es300,   // WebGL 2
    Es100,   // WebGL 1
};

ShaderDialect shaderDialectOf(const QByteArray &code);
bool hasVersionLine(const QByteArray &code);
// "GLSL ES 3.00 (WebGL 2)", "GLSL ES 1.00 (WebGL 1)", "desktop GLSL".
QString shaderDialectName(ShaderDialect dialect);

} // namespace phonglab
