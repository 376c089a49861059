#include "ShaderProgram.h"

#include <glm/gtc/type_ptr.hpp>

namespace phonglab {

namespace {

QString infoLog(QOpenGLExtraFunctions *gl, GLuint object, bool isProgram)
{
    GLint length = 0;
    if (isProgram)
        gl->glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        gl->glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    if (length <= 1)
        return {};
    QByteArray log(length, '\0');
    if (isProgram)
        gl->glGetProgramInfoLog(object, length, nullptr, log.data());
    else
        gl->glGetShaderInfoLog(object, length, nullptr, log.data());
    return QString::fromUtf8(log.constData());
}

// A failed step must always say why, even when the driver's log is empty
// or in a form the parser does not know.
void ensureError(CompileResult &result, ShaderStage stage, const QString &file, const QString &log)
{
    for (const ShaderDiagnostic &d : result.diagnostics)
        if (d.isError() && d.stage == stage)
            return;
    ShaderDiagnostic d;
    d.stage = stage;
    d.file = file;
    d.message = log.trimmed().isEmpty() ? QStringLiteral("%1 failed without a message from the driver")
                                               .arg(stage == ShaderStage::Link ? "linking" : "compiling")
                                        : log.trimmed();
    result.diagnostics.push_back(d);
}

} // namespace

GLuint ShaderProgram::compileStage(GLenum type, const ShaderSource &source,
                                   const QStringList &defines, CompileResult &result)
{
    const ShaderStage stage = type == GL_VERTEX_SHADER ? ShaderStage::Vertex : ShaderStage::Fragment;
    const QByteArray code = withPrologue(source.code, defines);
    const char *text = code.constData();
    const GLint length = GLint(code.size());

    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &text, &length);
    glCompileShader(shader);

    GLint status = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &status);
    const QString log = infoLog(this, shader, false);
    auto diagnostics = parseShaderLog(log, stage, source.name);
    mapColumnsToSource(diagnostics, source.code);
    result.diagnostics.insert(result.diagnostics.end(), diagnostics.begin(), diagnostics.end());
    if (status != GL_TRUE) {
        ensureError(result, stage, source.name, log);
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

CompileResult ShaderProgram::build(const ShaderSource &vertex, const ShaderSource &fragment,
                                   const QStringList &defines)
{
    if (!m_initialized) {
        initializeOpenGLFunctions();
        m_initialized = true;
    }
    CompileResult result;
    const GLuint vs = compileStage(GL_VERTEX_SHADER, vertex, defines, result);
    const GLuint fs = compileStage(GL_FRAGMENT_SHADER, fragment, defines, result);
    if (!vs || !fs) {
        if (vs) glDeleteShader(vs);
        if (fs) glDeleteShader(fs);
        return result;
    }

    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs); // flagged; freed with the program
    glDeleteShader(fs);

    GLint status = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &status);
    const QString log = infoLog(this, program, true);
    const QString linkName = vertex.name + QLatin1Char('+') + fragment.name;
    auto diagnostics = parseShaderLog(log, ShaderStage::Link, linkName);
    result.diagnostics.insert(result.diagnostics.end(), diagnostics.begin(), diagnostics.end());
    if (status != GL_TRUE) {
        ensureError(result, ShaderStage::Link, linkName, log);
        glDeleteProgram(program);
        return result;
    }

    destroy();
    m_program = program;
    result.ok = true;
    return result;
}

void ShaderProgram::destroy()
{
    if (m_program)
        glDeleteProgram(m_program);
    m_program = 0;
    m_locations.clear();
}

void ShaderProgram::bind()
{
    glUseProgram(m_program);
}

GLint ShaderProgram::uniformLocation(const char *name)
{
    const QByteArray key(name);
    auto it = m_locations.constFind(key);
    if (it != m_locations.constEnd())
        return *it;
    const GLint location = glGetUniformLocation(m_program, name);
    m_locations.insert(key, location);
    return location;
}

// A uniform the user's shader does not declare (or the compiler optimised
// away) has location -1; glUniform* ignores it, which is what we want.
void ShaderProgram::setUniform(const char *name, const glm::mat4 &m)
{
    glUniformMatrix4fv(uniformLocation(name), 1, GL_FALSE, glm::value_ptr(m));
}

void ShaderProgram::setUniform(const char *name, const glm::mat3 &m)
{
    glUniformMatrix3fv(uniformLocation(name), 1, GL_FALSE, glm::value_ptr(m));
}

void ShaderProgram::setUniform(const char *name, const glm::vec3 &v)
{
    glUniform3fv(uniformLocation(name), 1, glm::value_ptr(v));
}

void ShaderProgram::setUniform(const char *name, float f)
{
    glUniform1f(uniformLocation(name), f);
}

void ShaderProgram::setUniform(const char *name, int i)
{
    glUniform1i(uniformLocation(name), i);
}

void ShaderProgram::setUniformArray(const char *name, const glm::vec3 *values, int count)
{
    if (count > 0)
        glUniform3fv(uniformLocation(name), count, glm::value_ptr(values[0]));
}

} // namespace phonglab
