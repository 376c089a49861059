#pragma once
#include "core/program/ShaderBindings.h"

#include <QByteArray>
#include <QOpenGLExtraFunctions>
#include <QString>
#include <vector>

namespace phonglab {

// One active default-block uniform of a linked program, as the driver
// reports it (glGetActiveUniform). Arrays are one entry named without the
// "[0]"; `size` is the number of active elements.
struct ActiveUniformInfo {
    QByteArray name;
    GLenum type = 0;
    GLint size = 1;
    bool isArray = false;
    GLint location = -1; // of element 0
};

// The program's active uniforms outside uniform blocks, built-ins (gl_*)
// left out, sorted by name. Needs `program`'s context current.
std::vector<ActiveUniformInfo> activeUniformsOf(QOpenGLExtraFunctions *gl, GLuint program);

// The program's active vertex inputs (glGetActiveAttrib), built-ins left out.
struct ActiveInputInfo {
    QByteArray name;
    GLenum type = 0;
    GLint location = -1;
};
std::vector<ActiveInputInfo> activeInputsOf(QOpenGLExtraFunctions *gl, GLuint program);

// The type as bindings see it (GlslType::Other for samplers, ints vectors, ...).
GlslType glslTypeOf(GLenum type);
// Every active uniform and vertex input, as core/ShaderBindings takes them.
std::vector<ShaderVariable> shaderVariablesOf(QOpenGLExtraFunctions *gl, GLuint program);

// The text of each stage the program was linked from, as the driver was
// handed it (glGetShaderSource), with what PhongLab put before the
// student's `#line` turned into blank lines: the student's lines, numbered
// as in their file, whichever path built the program (the build thread,
// the window's trial, the CLI). Empty for a stage it cannot read.
struct CompiledStages {
    QByteArray vertex;
    QByteArray fragment;
};
CompiledStages compiledStagesOf(QOpenGLExtraFunctions *gl, GLuint program);

// GLSL spelling of a uniform type ("vec3", "sampler2D"); empty if unknown.
QString glslTypeName(GLenum type);

} // namespace phonglab
