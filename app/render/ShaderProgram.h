#pragma once
#include "BuildReport.h"
#include "ShaderSource.h"
#include "SharedGlObject.h"
#include "UniformSnapshot.h"

#include <QHash>
#include <QOpenGLExtraFunctions>
#include <glm/glm.hpp>

namespace phonglab {

// The program the renderer draws with, and its uniforms. build() builds
// one with ProgramBuilder on the current context; adopt() takes one built
// elsewhere (the BuildThread's context shares objects with this one).
// Requires a current context for every call; destroy() before the context
// goes away.
class ShaderProgram : protected QOpenGLExtraFunctions
{
public:
    ShaderProgram() = default;
    ShaderProgram(const ShaderProgram &) = delete;
    ShaderProgram &operator=(const ShaderProgram &) = delete;
    ~ShaderProgram() =
        default; // frees the program if a context of its group is current; see destroy()

    // Builds a new program. On failure the previous program (if any) stays
    // in place and usable; the result carries the diagnostics.
    BuildReport build(const ShaderSource &vertex, const ShaderSource &fragment,
                      const QStringList &defines = {});
    // Takes a program linked elsewhere (ProgramBuilder, possibly on another
    // context of the same share group) and frees the previous one.
    void adopt(GlProgram program);
    void destroy();

    // Every active default-block uniform's current value (double types are
    // left out: GL 3.3 has none, and glGetUniformdv is not in the ES-based
    // function set). restore() sets each value whose name AND type match an
    // active uniform of this program; the rest are skipped. It binds the
    // program for the duration and puts the previously bound one back.
    UniformSnapshot snapshot();
    void restore(const UniformSnapshot &snapshot);

    bool isValid() const { return bool(m_program); }
    GLuint id() const { return m_program.id(); }
    // Whether the program reads a `facePoint` attribute (flat.vert): it is
    // drawn from the meshes' face layouts then.
    bool readsFacePoint() const { return m_readsFacePoint; }
    void bind();

    GLint uniformLocation(const char *name);
    void setUniform(const char *name, const glm::mat4 &m);
    void setUniform(const char *name, const glm::mat3 &m);
    void setUniform(const char *name, const glm::vec3 &v);
    void setUniform(const char *name, float f);
    void setUniform(const char *name, int i);
    void setUniformArray(const char *name, const glm::vec3 *values, int count);

private:
    void ensureInitialized();
    void readValue(GLint location, UniformValue &value);
    void writeValue(GLint location, const UniformValue &value);

    bool m_initialized = false;
    GlProgram m_program;
    bool m_readsFacePoint = false;
    QHash<QByteArray, GLint> m_locations;
};

} // namespace phonglab
