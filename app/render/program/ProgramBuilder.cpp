#include "ProgramBuilder.h"

#include "UniformIntrospection.h"
#include "core/program/BrowserRules.h"
#include "core/program/ShaderDialect.h"
#include "core/program/ShaderLint.h"
#include "core/program/WebGl1Limits.h"

#include <QCoreApplication>
#include <QElapsedTimer>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ProgramBuilderWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ProgramBuilder)
};

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
        ? ProgramBuilderWords::tr("%1 failed without a message from the driver")
              .arg(step == BuildStep::Link ? "linking" : "compiling")
        : log.trimmed();
    result.diagnostics.push_back(d);
}

// Where the meshes feed each vertex input (GpuMesh's attribute arrays).
std::optional<GLuint> meshLocation(BindingMeaning meaning)
{
    switch (meaning) {
    case BindingMeaning::Position: return 0;
    case BindingMeaning::Normal: return 1;
    default: return std::nullopt;
    }
}

// What the driver's words mean for a student's dialect, said plainly.
void explainDialect(std::vector<ShaderDiagnostic> &diagnostics, ShaderDialect dialect)
{
    for (ShaderDiagnostic &d : diagnostics) {
        if (!d.isError())
            continue;
        const QString m = d.message;
        if (dialect == ShaderDialect::Es100
            && (m.contains(QLatin1StringView("inverse"))
                || m.contains(QLatin1StringView("transpose"))))
            d.message += ProgramBuilderWords::tr(
                " (GLSL ES 1.00, WebGL 1, has no inverse() or transpose(): write #version 300 es, "
                "or pass the normal matrix in as a uniform)");
        else if (dialect != ShaderDialect::Desktop && m.contains(QLatin1StringView("not supported"))
                 && m.contains(QLatin1StringView("version")))
            d.message +=
                ProgramBuilderWords::tr(" (this OpenGL driver does not run %1 shaders in a desktop "
                                        "context: it lacks ARB_ES%2_compatibility)")
                    .arg(shaderDialectName(dialect),
                         dialect == ShaderDialect::Es300 ? QStringLiteral("3")
                                                         : QStringLiteral("2"));
    }
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
                                      const QStringList &defines, const CourseOptions &course,
                                      BuildReport &result)
{
    const BuildStep step =
        type == GL_VERTEX_SHADER ? BuildStep::CompileVertex : BuildStep::CompileFragment;
    const ShaderStage stage =
        type == GL_VERTEX_SHADER ? ShaderStage::Vertex : ShaderStage::Fragment;
    const CoursePrelude prelude = coursePreludeFor(source.code, stage, course);
    // What the browser's WebGL does to the text (unset values start at
    // zero), on the student's own lines.
    const BrowserRewrite browser = applyBrowserRules(source.code, stage);
    for (const QString &added : prelude.added) {
        ShaderDiagnostic d;
        d.step = step;
        d.severity = ShaderDiagnostic::Severity::Warning;
        d.file = source.name;
        d.message = added;
        result.diagnostics.push_back(d);
    }
    const QByteArray code = withPrologue(browser.code, defines, prelude.text);
    const char *text = code.constData();
    const GLint length = GLint(code.size());

    GlShader shader(glCreateShader(type));
    glShaderSource(shader.id(), 1, &text, &length);
    glCompileShader(shader.id());

    GLint status = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &status);
    const QString log = infoLog(shader.id(), false);
    auto diagnostics = parseShaderLog(log, step, source.name);
    mapColumnsToSource(diagnostics, browser.code);
    for (ShaderDiagnostic &d : diagnostics)
        if (d.line > 0 && d.column > 0)
            d.column = browser.sourceColumn(d.line, d.column);
    pointAtMissingSemicolons(diagnostics, source.code);
    explainDialect(diagnostics, shaderDialectOf(source.code));
    for (ShaderDiagnostic &d : diagnostics)
        if (d.isError())
            d.message = explainUndefinedToken(d.message, course.defines);
    // What the image cannot show (a value GLSL leaves undefined): a warning
    // on the student's line, never a verdict.
    for (const LintFinding &f : lintShader(source.code))
        diagnostics.push_back(
            {step, ShaderDiagnostic::Severity::Warning, source.name, f.line, f.column, f.message});
    // What the browser refuses in WebGL 1, this driver accepts: refused here too.
    const std::vector<WebGlRefusal> refused = webGl1Refusals(source.code);
    for (const WebGlRefusal &r : refused)
        diagnostics.push_back(
            {step, ShaderDiagnostic::Severity::Error, source.name, r.line, r.column, r.message});
    result.diagnostics.insert(result.diagnostics.end(), diagnostics.begin(), diagnostics.end());
    if (status != GL_TRUE) {
        ensureError(result, step, source.name, log);
        return {};
    }
    if (!refused.empty())
        return {};
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

// Binds each input that means the position or the normal to the mesh's
// location and links again when one was elsewhere. False when that link
// failed (it cannot, but a driver's word is final).
bool ProgramBuilder::placeInputs(GLuint program, const ExplicitBindings &bindings,
                                 const QString &linkName, BuildReport &result)
{
    bool moved = false;
    for (const ActiveInputInfo &input : activeInputsOf(this, program)) {
        const ShaderVariable variable{QString::fromUtf8(input.name), glslTypeOf(input.type), 1,
                                      false, true};
        const auto it = bindings.find(variable.name);
        const std::optional<BindingMeaning> meaning =
            it != bindings.end() ? it->second : automaticMeaning(variable);
        const std::optional<GLuint> location = meaning ? meshLocation(*meaning) : std::nullopt;
        if (location && GLint(*location) != input.location) {
            glBindAttribLocation(program, *location, input.name.constData());
            moved = true;
        }
    }
    if (!moved)
        return true;
    glLinkProgram(program);
    GLint status = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &status);
    if (status != GL_TRUE)
        ensureError(result, BuildStep::Link, linkName, infoLog(program, true));
    return status == GL_TRUE;
}

BuiltProgram ProgramBuilder::build(const ShaderSource &vertex, const ShaderSource &fragment,
                                   const QStringList &defines, const ExplicitBindings &bindings,
                                   const CourseOptions &course)
{
    if (!m_initialized) {
        initializeOpenGLFunctions();
        m_initialized = true;
    }
    BuiltProgram out;
    QElapsedTimer timer;
    timer.start();
    const GlShader vs = compileStage(GL_VERTEX_SHADER, vertex, defines, course, out.report);
    const GlShader fs = compileStage(GL_FRAGMENT_SHADER, fragment, defines, course, out.report);
    out.compileNs = timer.nsecsElapsed();
    if (!vs || !fs)
        return out;
    timer.restart();
    const QString linkName = vertex.name + QLatin1Char('+') + fragment.name;
    out.program = link(vs, fs, linkName, out.report);
    if (out.program && !placeInputs(out.program.id(), bindings, linkName, out.report))
        out.program = {};
    if (!out.program) {
        const ShaderDialect v = shaderDialectOf(vertex.code), f = shaderDialectOf(fragment.code);
        if (v != f)
            out.report.diagnostics.insert(
                out.report.diagnostics.begin(),
                {BuildStep::Link, ShaderDiagnostic::Severity::Error, linkName, 0, 0,
                 ProgramBuilderWords::tr(
                     "the vertex shader is %1 and the fragment shader %2: both stages "
                     "must be written in the same GLSL (give both files)")
                     .arg(shaderDialectName(v), shaderDialectName(f))});
    }
    out.linkNs = timer.nsecsElapsed();
    out.report.ok = out.ok();
    return out;
}

} // namespace phonglab
