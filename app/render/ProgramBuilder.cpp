#include "ProgramBuilder.h"

#include <QElapsedTimer>

namespace phonglab {

namespace {

// A failed step must always say why, even when the driver's log is empty
// or in a form the parser does not know.
void ensureError(BuildReport &result, BuildStep step, const QString &file, const QString &log)
{
    for (const ShaderDiagnostic &d : result.diagnostics)
        if (d.isError() && d.step == step)
            return;
    ShaderDiagnostic d;
    d.step = step;
    d.file = file;
    d.message = log.trimmed().isEmpty() ? QStringLiteral("%1 failed without a message from the driver")
                                              .arg(step == BuildStep::Link ? "linking" : "compiling")
                                        : log.trimmed();
    result.diagnostics.push_back(d);
}

} // namespace

QString ProgramBuilder::infoLog(GLuint object, bool isProgram)
{
    GLint length = 0;
    if (isProgram)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    if (length <= 1)
        return {};
    QByteArray log(length, '\0');
    if (isProgram)
        glGetProgramInfoLog(object, length, nullptr, log.data());
    else
        glGetShaderInfoLog(object, length, nullptr, log.data());
    return QString::fromUtf8(log.constData());
}

GLuint ProgramBuilder::compileStage(GLenum type, const ShaderSource &source, const QStringList &defines,
                                    BuildReport &result)
{
    const BuildStep step = type == GL_VERTEX_SHADER ? BuildStep::CompileVertex : BuildStep::CompileFragment;
    const QByteArray code = withPrologue(source.code, defines);
    const char *text = code.constData();
    const GLint length = GLint(code.size());

    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &text, &length);
    glCompileShader(shader);

    GLint status = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &status);
    const QString log = infoLog(shader, false);
    auto diagnostics = parseShaderLog(log, step, source.name);
    mapColumnsToSource(diagnostics, source.code);
    result.diagnostics.insert(result.diagnostics.end(), diagnostics.begin(), diagnostics.end());
    if (status != GL_TRUE) {
        ensureError(result, step, source.name, log);
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

GLuint ProgramBuilder::link(GLuint vs, GLuint fs, const QString &linkName, BuildReport &result)
{
    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs); // flagged; freed with the program
    glDeleteShader(fs);

    GLint status = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &status);
    const QString log = infoLog(program, true);
    auto diagnostics = parseShaderLog(log, BuildStep::Link, linkName);
    result.diagnostics.insert(result.diagnostics.end(), diagnostics.begin(), diagnostics.end());
    if (status != GL_TRUE) {
        ensureError(result, BuildStep::Link, linkName, log);
        glDeleteProgram(program);
        return 0;
    }
    return program;
}

BuiltProgram ProgramBuilder::build(const ShaderSource &vertex, const ShaderSource &fragment, const QStringList &defines)
{
    if (!m_initialized) {
        initializeOpenGLFunctions();
        m_initialized = true;
    }
    BuiltProgram out;
    QElapsedTimer timer;
    timer.start();
    const GLuint vs = compileStage(GL_VERTEX_SHADER, vertex, defines, out.result);
    const GLuint fs = compileStage(GL_FRAGMENT_SHADER, fragment, defines, out.result);
    out.compileNs = timer.nsecsElapsed();
    if (!vs || !fs) {
        if (vs)
            glDeleteShader(vs);
        if (fs)
            glDeleteShader(fs);
        return out;
    }
    timer.restart();
    out.program = link(vs, fs, vertex.name + QLatin1Char('+') + fragment.name, out.result);
    out.linkNs = timer.nsecsElapsed();
    out.result.ok = out.program != 0;
    return out;
}

} // namespace phonglab
