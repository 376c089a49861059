#pragma once
#include "BuildReport.h"
#include "ShaderSource.h"
#include "UniformSnapshot.h"
#include "core/program/CoursePrelude.h"
#include "core/program/ShaderBindings.h"
#include "render/gl/SharedGlObject.h"

#include <QHash>
#include <QOpenGLExtraFunctions>
#include <array>
#include <glm/glm.hpp>
#include <span>

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
    // Puts `program` in place and hands the one in use back through it,
    // freeing neither: a trial of a new program that may be undone.
    void exchange(GlProgram &program);
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

    // PhongLab's values reach the program under whatever names it gives
    // them (core/ShaderBindings): each setter below sets every uniform bound
    // to `meaning`, converted to the uniform's type (a mat3 takes a mat4's
    // upper 3x3, a vec4 takes a point with w = 1 and a direction with
    // w = 0, an int takes a count). Meanings nothing is bound to cost a
    // lookup and nothing else.
    void setExplicitBindings(const ExplicitBindings &bindings);
    const ExplicitBindings &explicitBindings() const { return m_explicit; }
    // How build() hands the stages to the driver (core/program/CoursePrelude).
    void setCourseOptions(const CourseOptions &course) { m_course = course; }
    const CourseOptions &courseOptions() const { return m_course; }
    const ProgramBindings &bindings() const { return m_bindings; }
    void setMatrix(BindingMeaning meaning, const glm::dmat4 &m);
    void setMatrix(BindingMeaning meaning, const glm::dmat3 &m);
    void setVector(BindingMeaning meaning, const glm::dvec3 &v, double w = 1.0);
    void setScalar(BindingMeaning meaning, double value);
    // One value per light: an array takes the first of them, a single
    // uniform (or a member of "uLights[k]") the one of its light index.
    void setPerLight(BindingMeaning meaning, std::span<const glm::dvec3> values, double w = 1.0);
    void setPerLight(BindingMeaning meaning, std::span<const double> values);

    // Where `name` is (-1: not an active uniform), looked up once: for what
    // no meaning covers, such as tests setting a program's own uniforms.
    GLint uniformLocation(const char *name);

private:
    void ensureInitialized();
    void readValue(GLint location, UniformValue &value);
    void writeValue(GLint location, const UniformValue &value);
    void resolveBindings();

    // A uniform bound to a meaning, where to write it.
    struct BoundUniform {
        GLint location = -1;
        GlslType type = GlslType::Other;
        int arraySize = 1;
        bool isArray = false;
        int lightIndex = 0;
    };
    static constexpr std::size_t kMeanings = kBindingMeaningCount;
    const std::vector<BoundUniform> &targets(BindingMeaning meaning) const
    {
        return m_targets[std::size_t(meaning)];
    }

    bool m_initialized = false;
    GlProgram m_program;
    bool m_readsFacePoint = false;
    QHash<QByteArray, GLint> m_locations;
    ExplicitBindings m_explicit;
    CourseOptions m_course;
    ProgramBindings m_bindings;
    std::array<std::vector<BoundUniform>, kMeanings> m_targets;
};

} // namespace phonglab
