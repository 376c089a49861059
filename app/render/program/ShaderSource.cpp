#include "ShaderSource.h"

#include "core/program/ShaderDialect.h"
#include "core/project/ProjectShader.h"
#include "core/scene/ResourcePaths.h"

#include <QCoreApplication>
#include <QFile>

namespace phonglab {

namespace {
struct ShaderSourceWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ShaderSource)
};
} // namespace

Result<ShaderSource> ShaderSource::fromFile(const QString &path)
{
    // "index.html#fragment-shader": a shader inside a WebGL project's
    // file, laid out so its lines are the file's, reported under the file.
    if (isShaderLocator(path)) {
        Result<ProjectShader> shader = shaderAtLocator(path);
        if (!shader)
            return fail(shader.error());
        return ShaderSource{shader->file, std::move(shader->code)};
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(
            ShaderSourceWords::tr("%1: cannot read shader: %2").arg(path, file.errorString()));
    return ShaderSource{path, file.readAll()};
}

Result<ShaderSource> ShaderSource::forEditing(const QString &path)
{
    if (!isShaderLocator(path))
        return fromFile(path);
    Result<ProjectShader> shader = shaderAtLocator(path);
    if (!shader)
        return fail(shader.error());
    return ShaderSource{path, std::move(shader->text)};
}

Result<StageSources> readStageFiles(const QString &vertexPath, const QString &fragmentPath)
{
    Result<ShaderSource> vertex = ShaderSource::fromFile(vertexPath);
    if (!vertex)
        return fail(vertex.error());
    Result<ShaderSource> fragment = ShaderSource::fromFile(fragmentPath);
    if (!fragment)
        return fail(fragment.error());
    return StageSources{std::move(*vertex), std::move(*fragment)};
}

Result<StageSources> readShippedStages(ShadingMethod method)
{
    return readStageFiles(shippedShaderPath(method, ShaderStage::Vertex),
                          shippedShaderPath(method, ShaderStage::Fragment));
}

namespace {

// Index just past the line holding `#version`, or 0 if the first directive
// is something else. Comments and blank lines may come before #version.
qsizetype endOfVersionLine(const QByteArray &code, int *versionLine)
{
    qsizetype pos = 0;
    int line = 1;
    while (pos < code.size()) {
        const qsizetype eol = code.indexOf('\n', pos);
        const qsizetype end = eol < 0 ? code.size() : eol;
        const QByteArray text = code.mid(pos, end - pos).trimmed();
        if (text.startsWith("#version")) {
            *versionLine = line;
            return eol < 0 ? code.size() : eol + 1;
        }
        if (!text.isEmpty() && !text.startsWith("//"))
            return 0;
        pos = end + 1;
        ++line;
    }
    return 0;
}

// GLSL 3.30 and ES 3.00 on: after "#line N" the next line is N. Before
// that (1.10-1.50) it was N + 1; Mesa numbers GLSL ES 1.00 the new way
// (tst_bringyourownshader sees errors land on the user's lines).
int lineDirectiveFor(int nextLine, const QByteArray &versionHead)
{
    const qsizetype at = versionHead.indexOf("#version");
    if (at < 0)
        return nextLine;
    const int version = versionHead.mid(at + 8).trimmed().split(' ').value(0).toInt();
    // GLSL ES 1.00 ("#version 100", no "es") numbers as 3.30 does in Mesa.
    const bool es = versionHead.contains(" es") || version == 100;
    const bool newSemantics = es || version >= 330;
    return newSemantics ? nextLine : nextLine - 1;
}

} // namespace

QByteArray withPrologue(const QByteArray &code, const QStringList &defines,
                        const QByteArray &prelude)
{
    int versionLine = 0;
    const qsizetype split = endOfVersionLine(code, &versionLine);
    // No #version line: a WebGL 1 shader (core/ShaderDialect.h). GLSL ES
    // 1.00 must say so on its first line in a desktop context.
    const bool addVersion = !hasVersionLine(code);
    if (defines.isEmpty() && prelude.isEmpty() && !addVersion)
        return code;
    QByteArray head = addVersion ? QByteArray("#version 100\n") : code.left(split);
    if (split > 0 && !head.endsWith('\n'))
        head += '\n';
    QByteArray prologue = prelude;
    if (!prologue.isEmpty() && !prologue.endsWith('\n'))
        prologue += '\n';
    for (const QString &d : defines)
        prologue += "#define " + d.toUtf8() + '\n';
    prologue += "#line " + QByteArray::number(lineDirectiveFor(versionLine + 1, head)) + '\n';
    return head + prologue + code.mid(split);
}

} // namespace phonglab
