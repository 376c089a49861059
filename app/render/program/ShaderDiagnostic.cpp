#include "ShaderDiagnostic.h"

#include <QRegularExpression>

#include <cctype>

namespace phonglab {

ShaderStage editorStage(BuildStep step)
{
    return step == BuildStep::CompileVertex ? ShaderStage::Vertex : ShaderStage::Fragment;
}

QString stepName(BuildStep step)
{
    return step == BuildStep::Link ? QStringLiteral("link") : stageName(editorStage(step));
}

QString ShaderDiagnostic::format() const
{
    QString where = file.isEmpty() ? stepName(step) : file;
    if (line > 0) {
        where += QLatin1Char(':') + QString::number(line);
        if (column > 0)
            where += QLatin1Char(':') + QString::number(column);
    }
    const QLatin1String kind = isError() ? QLatin1String("error") : QLatin1String("warning");
    return QStringLiteral("%1: %2: %3").arg(where, kind, message);
}

namespace {

struct LogPattern {
    QRegularExpression regex;
    int line, column, severity, message; // capture indices (0 = absent)
};

const std::vector<LogPattern> &logPatterns()
{
    using RE = QRegularExpression;
    static const std::vector<LogPattern> patterns = {
        // Mesa: 0:12(5): error: message
        {RE(QStringLiteral(R"(^\s*\d+:(\d+)\((\d+)\):\s*(error|warning)\s*:\s*(.*)$)"),
            RE::CaseInsensitiveOption),
         1, 2, 3, 4},
        // NVIDIA: 0(12) : error C0000: message
        {RE(QStringLiteral(R"(^\s*\d+\((\d+)\)\s*:\s*(error|warning)\s*(?:[A-Z]\d+)?\s*:\s*(.*)$)"),
            RE::CaseInsensitiveOption),
         1, 0, 2, 3},
        // AMD / ANGLE / glslang: ERROR: 0:12: message
        {RE(QStringLiteral(R"(^\s*(error|warning)\s*:\s*\d+:(\d+)\s*:\s*(.*)$)"),
            RE::CaseInsensitiveOption),
         2, 0, 1, 3},
        // Unlocated (linker): error: message
        {RE(QStringLiteral(R"(^\s*(error|warning)\s*:\s*(.*)$)"), RE::CaseInsensitiveOption), 0, 0,
         1, 2},
    };
    return patterns;
}

ShaderDiagnostic fromMatch(const LogPattern &p, const QRegularExpressionMatch &m, BuildStep step,
                           const QString &file, int prologueLines)
{
    ShaderDiagnostic d;
    d.step = step;
    d.file = file;
    d.severity = m.captured(p.severity).compare(QLatin1String("warning"), Qt::CaseInsensitive) == 0
        ? ShaderDiagnostic::Severity::Warning
        : ShaderDiagnostic::Severity::Error;
    d.message = m.captured(p.message).trimmed();
    if (p.line) {
        const int driverLine = m.captured(p.line).toInt();
        d.line = driverLine > prologueLines ? driverLine - prologueLines : 0;
    }
    if (p.column && d.line > 0)
        d.column = m.captured(p.column).toInt();
    return d;
}

} // namespace

std::vector<ShaderDiagnostic> parseShaderLog(const QString &log, BuildStep step,
                                             const QString &file, int prologueLines)
{
    std::vector<ShaderDiagnostic> out;
    const QStringList lines = log.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (const QString &raw : lines) {
        const QString text = raw.trimmed();
        if (text.isEmpty())
            continue;
        bool matched = false;
        for (const LogPattern &p : logPatterns()) {
            const QRegularExpressionMatch m = p.regex.match(text);
            if (m.hasMatch()) {
                out.push_back(fromMatch(p, m, step, file, prologueLines));
                matched = true;
                break;
            }
        }
        // A continuation line (drivers wrap long messages): attach it to the
        // previous diagnostic rather than dropping it.
        if (!matched && !out.empty())
            out.back().message += QLatin1Char(' ') + text;
        else if (!matched) // banner or info text: keep it, but it decides nothing
            out.push_back({step, ShaderDiagnostic::Severity::Warning, file, 0, 0, text});
    }
    return out;
}

namespace {

// 1-based column in `line` of the character at 1-based column `collapsed`
// of the same line with each whitespace run collapsed to one space.
int uncollapseColumn(const QByteArray &line, int collapsed)
{
    int position = 0;
    for (int i = 0; i < line.size(); ++i) {
        const bool space = line[i] == ' ' || line[i] == '\t' || line[i] == '\r';
        if (space && i > 0 && (line[i - 1] == ' ' || line[i - 1] == '\t' || line[i - 1] == '\r'))
            continue; // still inside the same run
        if (++position == collapsed)
            return i + 1;
    }
    return 0;
}

} // namespace

namespace {

// The line's code without a trailing // comment or whitespace. Block
// comments are rare at a line's end and are left in.
QByteArray codeOf(const QByteArray &line)
{
    const qsizetype comment = line.indexOf("//");
    QByteArray code = comment >= 0 ? line.left(comment) : line;
    while (!code.isEmpty() && std::isspace(static_cast<unsigned char>(code.back())))
        code.chop(1);
    return code;
}

// Mesa: "syntax error, unexpected IDENTIFIER, expecting ',' or ';'"; other
// drivers say "';' expected" or "missing ';'".
bool expectsSemicolon(const QString &message)
{
    static const QRegularExpression pattern(
        QStringLiteral(R"(expecting[^\n]*['"];['"]|['"];['"] expected|missing ['"]?;)"));
    return pattern.match(message).hasMatch();
}

} // namespace

void pointAtMissingSemicolons(std::vector<ShaderDiagnostic> &diagnostics, const QByteArray &code)
{
    const QList<QByteArray> lines = code.split('\n');
    for (ShaderDiagnostic &d : diagnostics) {
        if (!d.isError() || d.line <= 1 || d.line > lines.size() || d.column <= 0
            || !expectsSemicolon(d.message))
            continue;
        if (!lines[d.line - 1].left(d.column - 1).trimmed().isEmpty())
            continue; // something before it on its line: the compiler's place is right
        for (int previous = d.line - 1; previous >= 1; --previous) {
            const QByteArray before = codeOf(lines[previous - 1]);
            if (before.isEmpty())
                continue;
            d.line = previous;
            d.column = int(before.size()) + 1;
            break;
        }
    }
}

void mapColumnsToSource(std::vector<ShaderDiagnostic> &diagnostics, const QByteArray &code)
{
    const QList<QByteArray> lines = code.split('\n');
    for (ShaderDiagnostic &d : diagnostics) {
        if (d.line <= 0 || d.column <= 0)
            continue;
        d.column = d.line <= lines.size() ? uncollapseColumn(lines[d.line - 1], d.column) : 0;
    }
}

} // namespace phonglab
