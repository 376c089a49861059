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
    d.message = log.trimmed().isEmpty()
        ? QStringLiteral("%1 failed without a message from the driver")
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

GlShader ProgramBuilder::compileStage(GLenum type, const ShaderSource &source,
                                      const QStringList &defines, BuildReport &result)
{
    const BuildStep step =
        type == GL_VERTEX_SHADER ? BuildStep::CompileVertex : BuildStep::CompileFragment;
    const QByteArray code = withPrologue(source.code, defines);
    const char *text = code.constData();
    const GLint length = GLint(code.size());

    GlShader shader(glCreateShader(type));
    glShaderSource(shader.id(), 1, &text, &length);
    glCompileShader(shader.id());

    GLint status = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &status);
    const QString log = infoLog(shader.id(), false);
    auto diagnostics = parseShaderLog(log, step, source.name);
    mapColumnsToSource(diagnostics, source.code);
    result.diagnostics.insert(result.diagnostics.end(), diagnostics.begin(), diagnostics.end());
    if (status != GL_TRUE) {
        ensureError(result, step, source.name, log);
        return {};
    }
    return shader;
}

// The shaders are freed when `vertex` and `fragment` go; attached, they are
// only flagged then, and live on with the program.
GlProgram ProgramBuilder::link(const GlShader &vertex, const GlShader &fragment,
                               const QString &linkName, BuildReport &result)
{
    GlProgram program(glCreateProgram());
    glAttachShader(program.id(), vertex.id());
    glAttachShader(program.id(), fragment.id());
    glLinkProgram(program.id());

    GLint status = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &status);
    const QString log = infoLog(program.id(), true);
    auto diagnostics = parseShaderLog(log, BuildStep::Link, linkName);
    result.diagnostics.insert(result.diagnostics.end(), diagnostics.begin(), diagnostics.end());
    if (status != GL_TRUE) {
        ensureError(result, BuildStep::Link, linkName, log);
        return {};
    }
    return program;
}

BuiltProgram ProgramBuilder::build(const ShaderSource &vertex, const ShaderSource &fragment,
                                   const QStringList &defines)
{
    if (!m_initialized) {
        initializeOpenGLFunctions();
        m_initialized = true;
    }
    BuiltProgram out;
    QElapsedTimer timer;
    timer.start();
    const GlShader vs = compileStage(GL_VERTEX_SHADER, vertex, defines, out.result);
    const GlShader fs = compileStage(GL_FRAGMENT_SHADER, fragment, defines, out.result);
    out.compileNs = timer.nsecsElapsed();
    if (!vs || !fs)
        return out;
    timer.restart();
    out.program = link(vs, fs, vertex.name + QLatin1Char('+') + fragment.name, out.result);
    out.linkNs = timer.nsecsElapsed();
    out.result.ok = out.ok();
    return out;
}

} // namespace phonglab
