#include "core/program/ShaderDialect.h"

#include <QList>

namespace phonglab {

namespace {

// The #version line's words after "#version", or empty where the first
// directive is something else (comments and blank lines may come first).
QList<QByteArray> versionWords(const QByteArray &code)
{
    for (const QByteArray &raw : code.split('\n')) {
        const QByteArray line = raw.trimmed();
        if (line.startsWith("#version"))
            return line.mid(8).simplified().split(' ');
        if (!line.isEmpty() && !line.startsWith("//"))
            return {};
    }
    return {};
}

} // namespace

bool hasVersionLine(const QByteArray &code)
{
    return !versionWords(code).isEmpty();
}

ShaderDialect shaderDialectOf(const QByteArray &code)
{
    const QList<QByteArray> words = versionWords(code);
    if (words.isEmpty() || words.first() == "100")
        return ShaderDialect::Es100;
    if (words.size() > 1 && words.at(1).startsWith("es"))
        return ShaderDialect::Es300;
    return ShaderDialect::Desktop;
}

QString shaderDialectName(ShaderDialect dialect)
{
    switch (dialect) {
    case ShaderDialect::Es300: return QStringLiteral("GLSL ES 3.00 (WebGL 2)");
    case ShaderDialect::Es100: return QStringLiteral("GLSL ES 1.00 (WebGL 1)");
    case ShaderDialect::Desktop: break;
    }
    return QStringLiteral("desktop GLSL");
}

} // namespace phonglab
