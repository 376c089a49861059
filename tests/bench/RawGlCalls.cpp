#define GL_GLEXT_PROTOTYPES 1

#include "RawGlCalls.h"

#include "core/view/ObjectMatrices.h"

#include "core/scene/ResourcePaths.h"

#include <QByteArray>
#include <QFile>
#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <vector>

namespace phonglab::bench {

void setPhongUniforms(GLuint p, const Scene &scene, const SceneObject &object, const QSize &size)
{
    const auto at = [p](const char *name) { return glGetUniformLocation(p, name); };
    const double aspect = double(size.width()) / size.height();
    const glm::dmat4 view = scene.camera.viewMatrix();
    const glm::dmat4 projection = scene.camera.projectionMatrix(aspect);
    const ObjectMatrices m = ObjectMatrices::make(object.transform.matrix(), view, projection);
    glUniformMatrix4fv(at("viewMatrix"), 1, GL_FALSE, glm::value_ptr(glm::mat4(view)));
    glUniformMatrix4fv(at("projectionMatrix"), 1, GL_FALSE, glm::value_ptr(glm::mat4(projection)));
    glUniformMatrix4fv(at("modelViewMatrix"), 1, GL_FALSE, glm::value_ptr(glm::mat4(m.modelView)));
    glUniformMatrix3fv(at("normalMatrix"), 1, GL_FALSE, glm::value_ptr(glm::mat3(m.normalMatrix)));
    glUniform3fv(at("Ia"), 1, glm::value_ptr(glm::vec3(scene.ambient)));
    glUniform3fv(at("ka"), 1, glm::value_ptr(glm::vec3(object.material.ka)));
    glUniform3fv(at("kd"), 1, glm::value_ptr(glm::vec3(object.material.kd)));
    glUniform3fv(at("ks"), 1, glm::value_ptr(glm::vec3(object.material.ks)));
    glUniform1f(at("shininess"), float(object.material.shininess));
    const int count = std::min<int>(int(scene.lights.size()), kMaxLights);
    glUniform1i(at("lightCount"), count);
    for (int i = 0; i < count; ++i) {
        const PointLight &l = scene.lights[i];
        const auto element = [&](const char *name) {
            return at(QByteArray(name).append('[').append(QByteArray::number(i)).append(']'));
        };
        glUniform3fv(element("lightPosition"), 1, glm::value_ptr(glm::vec3(l.position)));
        glUniform3fv(element("Id"), 1, glm::value_ptr(glm::vec3(l.diffuse)));
        glUniform3fv(element("Is"), 1, glm::value_ptr(glm::vec3(l.specular)));
        glUniform3fv(element("attenuation"), 1, glm::value_ptr(glm::vec3(l.attenuation)));
    }
}

GLuint compileShader(GLenum type, const QByteArray &text)
{
    const GLuint shader = glCreateShader(type);
    const char *source = text.constData();
    const GLint length = GLint(text.size());
    glShaderSource(shader, 1, &source, &length);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

GLuint linkProgram(const QByteArray &vertex, const QByteArray &fragment)
{
    const GLuint vs = compileShader(GL_VERTEX_SHADER, vertex);
    const GLuint fs = compileShader(GL_FRAGMENT_SHADER, fragment);
    GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint linked = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
        glDeleteProgram(program);
        program = 0;
    }
    return program;
}

QByteArray readShippedShader(const char *name)
{
    QFile file(shaderPath(QString::fromLatin1(name)));
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

RawMesh uploadMesh(const MeshData &mesh)
{
    std::vector<float> interleaved;
    interleaved.reserve(mesh.positions.size() * 6);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        interleaved.insert(interleaved.end(),
                           {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z,
                            mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z});
    RawMesh raw;
    glGenVertexArrays(1, &raw.vao);
    glBindVertexArray(raw.vao);
    glGenBuffers(1, &raw.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, raw.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)),
                 interleaved.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &raw.ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, raw.ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * 4), mesh.indices.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 24, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 24, reinterpret_cast<void *>(12));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    raw.indexCount = GLsizei(mesh.indices.size());
    return raw;
}

void deleteMesh(RawMesh &mesh)
{
    if (mesh.vao)
        glDeleteVertexArrays(1, &mesh.vao);
    const GLuint buffers[] = {mesh.vbo, mesh.ibo};
    if (mesh.vbo || mesh.ibo)
        glDeleteBuffers(2, buffers);
    mesh = RawMesh();
}

} // namespace phonglab::bench
