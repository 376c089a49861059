#pragma once
#include "core/Scene.h"

#include <QByteArray>
#include <QSize>
#include <QtGui/qopengl.h>

namespace phonglab::bench {

// The plain GL calls the raw-GL baselines share, made as a program without
// Qt's wrappers makes them.

// The shipped Phong program's uniforms for one object (glGetUniformLocation +
// glUniform*): what the baselines upload per draw.
void setPhongUniforms(GLuint program, const Scene &scene, const SceneObject &object,
                      const QSize &size);

// glCreateShader + glShaderSource + glCompileShader; 0 when it does not
// compile.
GLuint compileShader(GLenum type, const QByteArray &text);

} // namespace phonglab::bench
