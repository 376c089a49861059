#include "ShaderProgram.h"

#include "ProgramBuilder.h"
#include "UniformIntrospection.h"
#include "core/program/BindingsByUse.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <optional>

namespace phonglab {

namespace {

struct UniformLayout {
    UniformValue::Kind kind;
    int components;
};

// How many 32-bit words a uniform of `type` holds and how glUniform* takes
// them; nullopt for types that are not restored (doubles, images).
std::optional<UniformLayout> layoutOf(GLenum type)
{
    using K = UniformValue::Kind;
    switch (type) {
    case GL_FLOAT: return UniformLayout{K::Float, 1};
    case GL_FLOAT_VEC2: return UniformLayout{K::Float, 2};
    case GL_FLOAT_VEC3: return UniformLayout{K::Float, 3};
    case GL_FLOAT_VEC4: return UniformLayout{K::Float, 4};
    case GL_FLOAT_MAT2: return UniformLayout{K::Float, 4};
    case GL_FLOAT_MAT3: return UniformLayout{K::Float, 9};
    case GL_FLOAT_MAT4: return UniformLayout{K::Float, 16};
    case GL_FLOAT_MAT2x3:
    case GL_FLOAT_MAT3x2: return UniformLayout{K::Float, 6};
    case GL_FLOAT_MAT2x4:
    case GL_FLOAT_MAT4x2: return UniformLayout{K::Float, 8};
    case GL_FLOAT_MAT3x4:
    case GL_FLOAT_MAT4x3: return UniformLayout{K::Float, 12};
    case GL_INT:
    case GL_BOOL: return UniformLayout{K::Int, 1};
    case GL_INT_VEC2:
    case GL_BOOL_VEC2: return UniformLayout{K::Int, 2};
    case GL_INT_VEC3:
    case GL_BOOL_VEC3: return UniformLayout{K::Int, 3};
    case GL_INT_VEC4:
    case GL_BOOL_VEC4: return UniformLayout{K::Int, 4};
    case GL_UNSIGNED_INT: return UniformLayout{K::UInt, 1};
    case GL_UNSIGNED_INT_VEC2: return UniformLayout{K::UInt, 2};
    case GL_UNSIGNED_INT_VEC3: return UniformLayout{K::UInt, 3};
    case GL_UNSIGNED_INT_VEC4: return UniformLayout{K::UInt, 4};
    // Samplers hold a texture unit, set with glUniform1i.
    case GL_SAMPLER_1D:
    case GL_SAMPLER_2D:
    case GL_SAMPLER_3D:
    case GL_SAMPLER_CUBE:
    case GL_SAMPLER_1D_SHADOW:
    case GL_SAMPLER_2D_SHADOW:
    case GL_SAMPLER_CUBE_SHADOW:
    case GL_SAMPLER_1D_ARRAY:
    case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_2D_ARRAY_SHADOW:
    case GL_SAMPLER_2D_MULTISAMPLE:
    case GL_SAMPLER_BUFFER:
    case GL_SAMPLER_2D_RECT:
    case GL_INT_SAMPLER_2D:
    case GL_INT_SAMPLER_3D:
    case GL_INT_SAMPLER_CUBE:
    case GL_INT_SAMPLER_2D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_CUBE:
    case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY: return UniformLayout{K::Int, 1};
    default: return std::nullopt;
    }
}

QByteArray elementName(const ActiveUniformInfo &u, int element)
{
    return u.isArray ? u.name + '[' + QByteArray::number(element) + ']' : u.name;
}

} // namespace

void ShaderProgram::ensureInitialized()
{
    if (!m_initialized) {
        initializeOpenGLFunctions();
        m_initialized = true;
    }
}

BuildReport ShaderProgram::build(const ShaderSource &vertex, const ShaderSource &fragment,
                                 const QStringList &defines)
{
    ensureInitialized();
    BuiltProgram built = ProgramBuilder().build(vertex, fragment, defines, m_explicit, m_course);
    if (built.ok())
        adopt(std::move(built.program));
    return built.report;
}

void ShaderProgram::adopt(GlProgram program)
{
    ensureInitialized();
    destroy();
    m_program = std::move(program);
    // Asked once per program, not every frame (Renderer::drawObjects).
    m_readsFacePoint = m_program && glGetAttribLocation(m_program.id(), "facePoint") >= 0;
    resolveBindings();
}

void ShaderProgram::exchange(GlProgram &program)
{
    ensureInitialized();
    std::swap(m_program, program);
    m_readsFacePoint = m_program && glGetAttribLocation(m_program.id(), "facePoint") >= 0;
    resolveBindings();
}

void ShaderProgram::setExplicitBindings(const ExplicitBindings &bindings)
{
    if (bindings == m_explicit)
        return;
    m_explicit = bindings;
    if (m_program)
        resolveBindings();
}

void ShaderProgram::resolveBindings()
{
    for (auto &list : m_targets)
        list.clear();
    m_bindings = {};
    if (!m_program)
        return;
    m_bindings = bindVariables(shaderVariablesOf(this, m_program.id()), m_explicit);
    // Where no name decides, the use does: read from the program itself, so
    // that every path that builds one (build thread, trial, CLI) binds alike.
    const CompiledStages stages = compiledStagesOf(this, m_program.id());
    bindByUse(m_bindings, stages.vertex, stages.fragment);
    for (const VariableBinding &b : m_bindings.variables) {
        if (!b.meaning || b.variable.isInput)
            continue;
        const QByteArray name =
            b.variable.name.toUtf8() + (b.variable.isArray ? QByteArray("[0]") : QByteArray());
        const GLint location = glGetUniformLocation(m_program.id(), name.constData());
        if (location >= 0)
            m_targets[std::size_t(*b.meaning)].push_back({location, b.variable.type,
                                                          b.variable.arraySize, b.variable.isArray,
                                                          b.lightIndex});
    }
}

void ShaderProgram::setMatrix(BindingMeaning meaning, const glm::dmat4 &m)
{
    for (const BoundUniform &u : targets(meaning)) {
        if (u.type == GlslType::Mat4)
            glUniformMatrix4fv(u.location, 1, GL_FALSE, glm::value_ptr(glm::mat4(m)));
        else if (u.type == GlslType::Mat3)
            glUniformMatrix3fv(u.location, 1, GL_FALSE, glm::value_ptr(glm::mat3(m)));
    }
}

void ShaderProgram::setMatrix(BindingMeaning meaning, const glm::dmat3 &m)
{
    for (const BoundUniform &u : targets(meaning)) {
        if (u.type == GlslType::Mat3)
            glUniformMatrix3fv(u.location, 1, GL_FALSE, glm::value_ptr(glm::mat3(m)));
        else if (u.type == GlslType::Mat4) // the 3x3 in the upper left, no translation
            glUniformMatrix4fv(u.location, 1, GL_FALSE, glm::value_ptr(glm::mat4(glm::mat3(m))));
    }
}

void ShaderProgram::setVector(BindingMeaning meaning, const glm::dvec3 &v, double w)
{
    setPerLight(meaning, std::span<const glm::dvec3>(&v, 1), w);
}

void ShaderProgram::setScalar(BindingMeaning meaning, double value)
{
    setPerLight(meaning, std::span<const double>(&value, 1));
}

void ShaderProgram::setPerLight(BindingMeaning meaning, std::span<const glm::dvec3> values,
                                double w)
{
    for (const BoundUniform &u : targets(meaning)) {
        const std::size_t first = u.isArray ? 0 : std::size_t(u.lightIndex);
        if (first >= values.size())
            continue;
        const int count =
            u.isArray ? int(std::min<std::size_t>(values.size(), std::size_t(u.arraySize))) : 1;
        if (u.type == GlslType::Vec3) {
            std::vector<glm::vec3> packed(values.begin() + first, values.begin() + first + count);
            glUniform3fv(u.location, count, glm::value_ptr(packed[0]));
        } else if (u.type == GlslType::Vec4) {
            std::vector<glm::vec4> packed;
            for (int i = 0; i < count; ++i)
                packed.emplace_back(glm::vec3(values[first + std::size_t(i)]), float(w));
            glUniform4fv(u.location, count, glm::value_ptr(packed[0]));
        }
    }
}

void ShaderProgram::setPerLight(BindingMeaning meaning, std::span<const double> values)
{
    for (const BoundUniform &u : targets(meaning)) {
        const std::size_t first = u.isArray ? 0 : std::size_t(u.lightIndex);
        if (first >= values.size())
            continue;
        const int count =
            u.isArray ? int(std::min<std::size_t>(values.size(), std::size_t(u.arraySize))) : 1;
        if (u.type == GlslType::Float) {
            std::vector<float> packed(values.begin() + first, values.begin() + first + count);
            glUniform1fv(u.location, count, packed.data());
        } else if (u.type == GlslType::Int || u.type == GlslType::Bool) {
            std::vector<GLint> packed;
            for (int i = 0; i < count; ++i)
                packed.push_back(GLint(std::lround(values[first + std::size_t(i)])));
            glUniform1iv(u.location, count, packed.data());
        } else if (u.type == GlslType::UInt) {
            std::vector<GLuint> packed;
            for (int i = 0; i < count; ++i)
                packed.push_back(GLuint(std::lround(values[first + std::size_t(i)])));
            glUniform1uiv(u.location, count, packed.data());
        }
    }
}

void ShaderProgram::readValue(GLint location, UniformValue &value)
{
    switch (value.kind) {
    case UniformValue::Kind::Float:
        glGetUniformfv(m_program.id(), location, value.floats.data());
        break;
    case UniformValue::Kind::Int:
        glGetUniformiv(m_program.id(), location, value.ints.data());
        break;
    case UniformValue::Kind::UInt:
        glGetUniformuiv(m_program.id(), location, value.uints.data());
        break;
    }
}

UniformSnapshot ShaderProgram::snapshot()
{
    UniformSnapshot snapshot;
    if (!m_program)
        return snapshot;
    ensureInitialized();
    for (const ActiveUniformInfo &u : activeUniformsOf(this, m_program.id())) {
        const auto layout = layoutOf(u.type);
        if (!layout)
            continue;
        for (int element = 0; element < u.size; ++element) {
            UniformValue value;
            value.name = elementName(u, element);
            value.type = u.type;
            value.kind = layout->kind;
            value.components = layout->components;
            const GLint location = glGetUniformLocation(m_program.id(), value.name.constData());
            if (location < 0)
                continue;
            readValue(location, value);
            snapshot.values.push_back(value);
        }
    }
    return snapshot;
}

void ShaderProgram::writeValue(GLint location, const UniformValue &v)
{
    switch (v.type) {
    case GL_FLOAT_MAT2: glUniformMatrix2fv(location, 1, GL_FALSE, v.floats.data()); return;
    case GL_FLOAT_MAT3: glUniformMatrix3fv(location, 1, GL_FALSE, v.floats.data()); return;
    case GL_FLOAT_MAT4: glUniformMatrix4fv(location, 1, GL_FALSE, v.floats.data()); return;
    case GL_FLOAT_MAT2x3: glUniformMatrix2x3fv(location, 1, GL_FALSE, v.floats.data()); return;
    case GL_FLOAT_MAT3x2: glUniformMatrix3x2fv(location, 1, GL_FALSE, v.floats.data()); return;
    case GL_FLOAT_MAT2x4: glUniformMatrix2x4fv(location, 1, GL_FALSE, v.floats.data()); return;
    case GL_FLOAT_MAT4x2: glUniformMatrix4x2fv(location, 1, GL_FALSE, v.floats.data()); return;
    case GL_FLOAT_MAT3x4: glUniformMatrix3x4fv(location, 1, GL_FALSE, v.floats.data()); return;
    case GL_FLOAT_MAT4x3: glUniformMatrix4x3fv(location, 1, GL_FALSE, v.floats.data()); return;
    default: break;
    }
    const GLfloat *f = v.floats.data();
    const GLint *i = v.ints.data();
    const GLuint *u = v.uints.data();
    switch (v.kind) {
    case UniformValue::Kind::Float:
        v.components == 1       ? glUniform1fv(location, 1, f)
            : v.components == 2 ? glUniform2fv(location, 1, f)
            : v.components == 3 ? glUniform3fv(location, 1, f)
                                : glUniform4fv(location, 1, f);
        break;
    case UniformValue::Kind::Int:
        v.components == 1       ? glUniform1iv(location, 1, i)
            : v.components == 2 ? glUniform2iv(location, 1, i)
            : v.components == 3 ? glUniform3iv(location, 1, i)
                                : glUniform4iv(location, 1, i);
        break;
    case UniformValue::Kind::UInt:
        v.components == 1       ? glUniform1uiv(location, 1, u)
            : v.components == 2 ? glUniform2uiv(location, 1, u)
            : v.components == 3 ? glUniform3uiv(location, 1, u)
                                : glUniform4uiv(location, 1, u);
        break;
    }
}

void ShaderProgram::restore(const UniformSnapshot &snapshot)
{
    if (!m_program || snapshot.values.empty())
        return;
    ensureInitialized();
    GLint previous = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
    glUseProgram(m_program.id());
    for (const ActiveUniformInfo &u : activeUniformsOf(this, m_program.id())) {
        for (int element = 0; element < u.size; ++element) {
            const QByteArray name = elementName(u, element);
            const UniformValue *value = snapshot.find(name);
            // Same name, other type (float became vec3): the old value means
            // nothing to the new shader, which keeps its initialiser.
            if (!value || value->type != u.type)
                continue;
            const GLint location = glGetUniformLocation(m_program.id(), name.constData());
            if (location >= 0)
                writeValue(location, *value);
        }
    }
    glUseProgram(GLuint(previous));
}

void ShaderProgram::destroy()
{
    m_program.reset();
    m_locations.clear();
    m_readsFacePoint = false;
    for (auto &list : m_targets)
        list.clear();
    m_bindings = {};
}

void ShaderProgram::bind()
{
    glUseProgram(m_program.id());
}

GLint ShaderProgram::uniformLocation(const char *name)
{
    const QByteArray key(name);
    auto it = m_locations.constFind(key);
    if (it != m_locations.constEnd())
        return *it;
    const GLint location = glGetUniformLocation(m_program.id(), name);
    m_locations.insert(key, location);
    return location;
}

// A uniform the user's shader does not declare (or the compiler optimised
// away) has location -1; glUniform* ignores it, which is what we want.
} // namespace phonglab
