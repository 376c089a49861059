#include "core/program/UniformAnnotations.h"

#include <QRegularExpression>
#include <QStringList>
#include <cmath>

namespace phonglab {

namespace {

// Drops /* ... */ comments (kept line breaks so lines stay lines) but keeps
// // comments, which carry the annotations.
QString withoutBlockComments(const QString &source)
{
    QString out;
    out.reserve(source.size());
    bool inBlock = false;
    for (qsizetype i = 0; i < source.size(); ++i) {
        const QChar c = source[i];
        const QChar next = i + 1 < source.size() ? source[i + 1] : QChar();
        if (inBlock) {
            if (c == '*' && next == '/') {
                inBlock = false;
                ++i;
            } else if (c == '\n') {
                out += c;
            }
        } else if (c == '/' && next == '*') {
            inBlock = true;
            ++i;
        } else {
            out += c;
        }
    }
    return out;
}

std::optional<double> finiteNumber(const QString &text)
{
    bool ok = false;
    const double value = text.toDouble(&ok);
    if (!ok || !std::isfinite(value))
        return std::nullopt;
    return value;
}

// "gain" / "lights[MAX]" / "Id[8]" -> a declaration of `type`.
std::optional<UniformDeclaration> parseDeclarator(const QString &type, const QString &text)
{
    static const QRegularExpression declarator(
        QStringLiteral(R"(^\s*([A-Za-z_]\w*)\s*(?:\[\s*(\w*)\s*\])?\s*(?:=.*)?$)"));
    const QRegularExpressionMatch m = declarator.match(text);
    if (!m.hasMatch())
        return std::nullopt;
    UniformDeclaration d;
    d.type = type;
    d.name = m.captured(1);
    d.isArray = m.capturedStart(2) >= 0;
    if (d.isArray)
        d.arraySize = m.captured(2).toInt(); // 0 when a constant names the size
    return d;
}

} // namespace

void parseUniformAnnotations(const QString &comment, UniformDeclaration &declaration)
{
    const QStringList words =
        comment.split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts);
    for (qsizetype i = 0; i < words.size(); ++i) {
        const QString &word = words[i];
        if (word == QLatin1String("@color") || word == QLatin1String("@colour")) {
            declaration.color = true;
        } else if (word == QLatin1String("@range") && i + 2 < words.size()) {
            const auto low = finiteNumber(words[i + 1]);
            const auto high = finiteNumber(words[i + 2]);
            if (low && high && *low < *high) { // a reversed or empty range is ignored
                declaration.rangeLow = low;
                declaration.rangeHigh = high;
                i += 2;
            }
        } else if (word == QLatin1String("@step") && i + 1 < words.size()) {
            const auto step = finiteNumber(words[i + 1]);
            if (step && *step > 0) {
                declaration.step = step;
                ++i;
            }
        }
    }
}

std::vector<UniformDeclaration> parseUniformDeclarations(const QString &source)
{
    // [layout(...)] uniform [precision] type declarators ; [// comment]
    static const QRegularExpression line(QStringLiteral(
        R"(^\s*(?:layout\s*\([^)]*\)\s*)?uniform\s+(?:(?:lowp|mediump|highp)\s+)?([A-Za-z_]\w*)\s+([^;{]+);\s*(?://(.*))?$)"));
    std::vector<UniformDeclaration> list;
    const QStringList lines = withoutBlockComments(source).split(QLatin1Char('\n'));
    for (const QString &text : lines) {
        const QRegularExpressionMatch m = line.match(text);
        if (!m.hasMatch())
            continue;
        for (const QString &part : m.captured(2).split(QLatin1Char(','))) {
            std::optional<UniformDeclaration> d = parseDeclarator(m.captured(1), part);
            if (!d)
                continue;
            parseUniformAnnotations(m.captured(3), *d);
            list.push_back(*d);
        }
    }
    return list;
}

} // namespace phonglab
