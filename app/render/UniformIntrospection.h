#pragma once
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

// GLSL spelling of a uniform type ("vec3", "sampler2D"); empty if unknown.
QString glslTypeName(GLenum type);

} // namespace phonglab
