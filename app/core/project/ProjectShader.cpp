#include "ProjectShader.h"

#include "HtmlShaders.h"
#include "JsShaders.h"
#include "ProjectSave.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ProjectShaderWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ProjectShader)
};

namespace {

constexpr qint64 kMaxProjectFileBytes = 8 * 1024 * 1024; // a page or script, not a data file

bool suffixIn(const QString &path, const QStringList &suffixes)
{
    return suffixes.contains(QFileInfo(path).suffix().toLower());
}

// GLSL without its comments: a comment naming gl_Position decides nothing.
QByteArray withoutComments(const QByteArray &text)
{
    QByteArray out;
    out.reserve(text.size());
    for (qsizetype i = 0; i < text.size(); ++i) {
        if (text[i] == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            while (i < text.size() && text[i] != '\n')
                ++i;
        } else if (text[i] == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            const qsizetype end = text.indexOf("*/", i + 2);
            i = end < 0 ? text.size() : end + 1;
            continue;
        }
        if (i < text.size())
            out += text[i];
    }
    return out;
}

} // namespace

std::optional<ShaderStage> stageOfShaderText(const QByteArray &text)
{
    const QByteArray code = withoutComments(text);
    if (!code.contains("main"))
        return std::nullopt;
    if (code.contains("gl_Position"))
        return ShaderStage::Vertex;
    static const QRegularExpression out(QStringLiteral("\\bout\\s+(\\w+\\s+)*[iu]?vec4\\b"));
    if (code.contains("gl_FragColor") || code.contains("gl_FragData")
        || out.match(QString::fromUtf8(code)).hasMatch())
        return ShaderStage::Fragment;
    return std::nullopt;
}

namespace {

QByteArray laidOutAsInFile(const QByteArray &file, const QByteArray &value,
                           const std::vector<qsizetype> &from, int *firstLine)
{
    // Line starts of the file, for an offset's line and column.
    std::vector<qsizetype> lineStarts{0};
    for (qsizetype i = 0; i < file.size(); ++i)
        if (file[i] == '\n')
            lineStarts.push_back(i + 1);
    const auto lineOf = [&](qsizetype offset) {
        return int(std::upper_bound(lineStarts.begin(), lineStarts.end(), offset)
                   - lineStarts.begin());
    };
    QByteArray code;
    int codeLine = 1;
    bool lineStart = true;
    *firstLine = 0;
    for (qsizetype i = 0; i < value.size(); ++i) {
        const char c = value[i];
        if (lineStart && c != '\n' && i < qsizetype(from.size())) {
            const qsizetype at = from[std::size_t(i)];
            const int line = lineOf(at);
            if (*firstLine == 0)
                *firstLine = line;
            // Blank lines up to the file's line, unless the line before
            // continues into this one (a backslash ends it).
            const bool continued = code.endsWith("\\\n");
            while (codeLine < line && !continued) {
                code += '\n';
                ++codeLine;
            }
            const qsizetype column = at - lineStarts[std::size_t(line - 1)];
            code += QByteArray(column, ' ');
        }
        lineStart = c == '\n';
        if (c == '\n')
            ++codeLine;
        code += c;
    }
    if (*firstLine == 0)
        *firstLine = 1;
    return code;
}

void addFound(std::vector<ProjectShader> &out, const QString &path, const QByteArray &file,
              const FoundText &text)
{
    const std::optional<ShaderStage> stage = stageOfShaderText(text.value);
    if (!stage)
        return;
    ProjectShader shader;
    shader.file = path;
    shader.stage = *stage;
    shader.code = laidOutAsInFile(file, text.value, text.from, &shader.line);
    shader.key =
        text.name.isEmpty() ? ProjectShaderWords::tr("line %1").arg(shader.line) : text.name;
    shader.begin = text.begin;
    shader.end = text.end;
    shader.text = text.value;
    shader.container = text.container;
    shader.quote = text.quote;
    shader.notWritable = whyNotWritable(shader, file);
    shader.writable = shader.notWritable.isEmpty();
    for (const ProjectShader &other : out)
        if (other.key == shader.key) // two texts under one name: the later by its line
            shader.key = ProjectShaderWords::tr("line %1").arg(shader.line);
    out.push_back(std::move(shader));
}

} // namespace

std::vector<ProjectShader> shadersInFile(const QString &path)
{
    QFile f(path);
    if (f.size() > kMaxProjectFileBytes || !f.open(QIODevice::ReadOnly))
        return {};
    return shadersInText(path, f.readAll());
}

bool isPageFile(const QString &path)
{
    static const QStringList suffixes{QStringLiteral("html"), QStringLiteral("htm"),
                                      QStringLiteral("xhtml")};
    return suffixIn(path, suffixes);
}

bool isScriptFile(const QString &path)
{
    static const QStringList suffixes{QStringLiteral("js"), QStringLiteral("mjs"),
                                      QStringLiteral("cjs")};
    return suffixIn(path, suffixes);
}

std::vector<ProjectShader> shadersInText(const QString &path, const QByteArray &file)
{
    std::vector<ProjectShader> out;
    std::vector<FoundText> texts;
    if (isPageFile(path))
        texts = shaderTextsInHtml(file);
    else if (isScriptFile(path)
             || (hasShaderFileSuffix(path)
                 && holdsShaderStrings(file))) // a course's "shader file" that is JavaScript
        texts = foundInJs(file, 0);
    else if (hasShaderFileSuffix(path)) {
        FoundText whole;
        whole.value = file;
        whole.from.resize(std::size_t(file.size()));
        for (qsizetype i = 0; i < file.size(); ++i)
            whole.from[std::size_t(i)] = i;
        whole.name = QFileInfo(path).fileName();
        whole.begin = 0;
        whole.end = file.size();
        whole.container = ShaderContainer::File;
        texts.push_back(std::move(whole));
    }
    for (const FoundText &text : texts)
        addFound(out, path, file, text);
    return out;
}

QString shaderLocator(const ProjectShader &shader)
{
    return shader.file + QLatin1Char('#') + shader.key;
}

bool isShaderLocator(const QString &path)
{
    const qsizetype hash = path.lastIndexOf(QLatin1Char('#'));
    return hash > 0 && !QFileInfo(path).isFile() && QFileInfo(path.left(hash)).isFile();
}

Result<ProjectShader> shaderAtLocator(const QString &locator)
{
    const qsizetype hash = locator.lastIndexOf(QLatin1Char('#'));
    const QString file = locator.left(hash);
    const QString key = locator.mid(hash + 1);
    for (ProjectShader &shader : shadersInFile(file))
        if (shader.key == key)
            return std::move(shader);
    return fail(ProjectShaderWords::tr("%1: no shader named %2 in it").arg(file, key));
}

} // namespace phonglab
