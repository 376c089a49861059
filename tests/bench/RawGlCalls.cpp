#define GL_GLEXT_PROTOTYPES 1

#include "RawGlCalls.h"

#include "core/ObjectMatrices.h"

#include <QByteArray>
#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

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

} // namespace phonglab::bench
