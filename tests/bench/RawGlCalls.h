#pragma once
#include "core/scene/MeshData.h"
#include "core/scene/Scene.h"

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

// Both stages compiled and linked (glCreateProgram, glAttachShader,
// glLinkProgram); 0 when they do not link.
GLuint linkProgram(const QByteArray &vertex, const QByteArray &fragment);

// A shipped shader's text (empty when it cannot be read).
QByteArray readShippedShader(const char *name);

// A mesh in the layout of every scene mesh: position and normal interleaved
// (24 bytes a vertex, attributes 0 and 1), 32-bit indices, in a VAO.
struct RawMesh {
    GLuint vao = 0, vbo = 0, ibo = 0;
    GLsizei indexCount = 0;
};
RawMesh uploadMesh(const MeshData &mesh);
void deleteMesh(RawMesh &mesh); // and leaves it empty

} // namespace phonglab::bench
