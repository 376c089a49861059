#include "CoursePrelude.h"

#include "core/program/ShaderDialect.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <array>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct CoursePreludeWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::CoursePrelude)
};

QString precisionRuleKey(PrecisionRule rule)
{
    return rule == PrecisionRule::AsWritten ? QStringLiteral("as-written")
                                            : QStringLiteral("highp");
}

std::optional<PrecisionRule> precisionRuleFromKey(const QString &key)
{
    if (key == QLatin1StringView("highp"))
        return PrecisionRule::Highp;
    if (key == QLatin1StringView("as-written"))
        return PrecisionRule::AsWritten;
    return std::nullopt;
}

std::optional<ParsedDefine> parseDefineArgument(const QString &text, QString *error)
{
    static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_][A-Za-z0-9_]*$"));
    const qsizetype eq = text.indexOf(QLatin1Char('='));
    const QString name = (eq < 0 ? text : text.left(eq)).trimmed();
    const QString value = eq < 0 ? QString() : text.mid(eq + 1).trimmed();
    if (!identifier.match(name).hasMatch()) {
        *error = CoursePreludeWords::tr("expected NAME=VALUE with NAME a GLSL identifier, got '%1'")
                     .arg(text);
        return std::nullopt;
    }
    // A value is one line of the prelude: a line break would end the #define
    // and put the rest outside it.
    if (value.contains(QLatin1Char('\n')) || value.contains(QLatin1Char('\r'))) {
        *error = CoursePreludeWords::tr("'%1': the value must be one line").arg(name);
        return std::nullopt;
    }
    return ParsedDefine{name, value};
}

namespace {

// The code without comments (each replaced by a space, line breaks kept), so
// that a name in a comment neither declares nor uses anything.
QByteArray withoutComments(const QByteArray &code)
{
    QByteArray out;
    out.reserve(code.size());
    for (qsizetype i = 0; i < code.size(); ++i) {
        if (code[i] == '/' && i + 1 < code.size() && code[i + 1] == '/') {
            while (i < code.size() && code[i] != '\n')
                ++i;
            if (i < code.size())
                out += '\n';
        } else if (code[i] == '/' && i + 1 < code.size() && code[i + 1] == '*') {
            i += 2;
            while (i + 1 < code.size() && !(code[i] == '*' && code[i + 1] == '/')) {
                if (code[i] == '\n')
                    out += '\n';
                ++i;
            }
            ++i;
            out += ' ';
        } else {
            out += code[i];
        }
    }
    return out;
}

bool usesWord(const QString &code, const QString &word)
{
    return QRegularExpression(QStringLiteral("\\b%1\\b").arg(word)).match(code).hasMatch();
}

// A declaration of `name` by the source itself (uniform, attribute, in, a
// #define of that name, or a variable of its own: `mat3 normalMatrix = ...`
// in main() is no three.js built-in).
bool declares(const QString &code, const QString &name)
{
    const QRegularExpression declared(
        QStringLiteral(R"((?:\b(?:uniform|attribute|in)\b[^;{}]*\b%1\b)|(?:#\s*define\s+%1\b))"
                       R"(|(?:\b(?:[biu]?vec[234]|mat[234](?:x[234])?|float|u?int|bool)\s+%1\b))")
            .arg(name));
    return declared.match(code).hasMatch();
}

struct ThreeJsName {
    const char *name;
    const char *declaration;
    bool vertexOnly;
};

// What three.js's WebGLProgram prepends to a ShaderMaterial's stages (the
// built-in uniforms and attributes of its prefixVertex / prefixFragment),
// in GLSL ES 1.00 words.
constexpr std::array kThreeJsNames = {
    ThreeJsName{"modelMatrix", "uniform mat4 modelMatrix;", true},
    ThreeJsName{"modelViewMatrix", "uniform mat4 modelViewMatrix;", true},
    ThreeJsName{"projectionMatrix", "uniform mat4 projectionMatrix;", true},
    ThreeJsName{"viewMatrix", "uniform mat4 viewMatrix;", false},
    ThreeJsName{"normalMatrix", "uniform mat3 normalMatrix;", true},
    ThreeJsName{"cameraPosition", "uniform vec3 cameraPosition;", false},
    ThreeJsName{"position", "attribute vec3 position;", true},
    ThreeJsName{"normal", "attribute vec3 normal;", true},
};

// The declarations a three.js source leaves to three.js: only where the
// source uses one of its matrices undeclared (a plain `position` alone says
// nothing about three.js).
QByteArray threeJsDeclarations(const QString &code, ShaderStage stage, ShaderDialect dialect)
{
    bool three = false;
    for (const ThreeJsName &n : kThreeJsNames) {
        const QString name = QString::fromLatin1(n.name);
        if (name != QLatin1StringView("position") && name != QLatin1StringView("normal")
            && usesWord(code, name) && !declares(code, name))
            three = true;
    }
    if (!three)
        return {};
    QByteArray out;
    for (const ThreeJsName &n : kThreeJsNames) {
        const QString name = QString::fromLatin1(n.name);
        if ((stage == ShaderStage::Vertex || !n.vertexOnly) && usesWord(code, name)
            && !declares(code, name)) {
            QByteArray line(n.declaration);
            // GLSL ES 3.00 (three.js's GLSL3 materials) names inputs `in`.
            if (dialect == ShaderDialect::Es300 && line.startsWith("attribute "))
                line.replace(0, 9, "in");
            out += line + '\n';
        }
    }
    return out;
}

const QRegularExpression &defaultFloatPrecision()
{
    static const QRegularExpression re(
        QStringLiteral(R"(\bprecision\s+(lowp|mediump|highp)\s+float\s*;)"));
    return re;
}

} // namespace

CoursePrelude coursePreludeFor(const QByteArray &code, ShaderStage stage,
                               const CourseOptions &options)
{
    CoursePrelude out;
    const QString text = QString::fromUtf8(withoutComments(code));
    for (const char *lower : {"mediump", "lowp"})
        if (usesWord(text, QString::fromLatin1(lower)))
            out.lowerPrecisions << QString::fromLatin1(lower);

    const ShaderDialect dialect = shaderDialectOf(code);
    const QByteArray three = threeJsDeclarations(text, stage, dialect);
    out.usesThreeJs = !three.isEmpty();
    const bool es = dialect != ShaderDialect::Desktop;
    // three.js and WebGL pages put precision first; a GLSL ES fragment
    // shader cannot compile without one.
    if (out.usesThreeJs) {
        out.text += "precision highp float;\nprecision highp int;\n";
        out.text += three;
        out.added << CoursePreludeWords::tr(
            "three.js's ShaderMaterial prelude added (its built-in uniforms and attributes, "
            "precision highp), as three.js adds it");
    } else if (es && stage == ShaderStage::Fragment
               && !defaultFloatPrecision().match(text).hasMatch()) {
        out.text += "precision highp float;\n";
        out.added << CoursePreludeWords::tr(
            "no default float precision: checked with 'precision highp float;' added, as the "
            "page's JavaScript adds it");
    }
    if (options.precision == PrecisionRule::Highp && !out.lowerPrecisions.isEmpty()) {
        for (const QString &lower : out.lowerPrecisions)
            out.text += "#define " + lower.toLatin1() + " highp\n";
        out.added << CoursePreludeWords::tr(
                         "%1 checked at highp (32-bit floats), as a desktop browser computes it "
                         "(--precision as-written for this driver's own)")
                         .arg(out.lowerPrecisions.join(QStringLiteral(", ")));
    }
    for (const auto &[name, value] : options.defines)
        out.text += "#define " + name.toUtf8()
            + (value.isEmpty() ? QByteArray() : ' ' + value.toUtf8()) + '\n';
    return out;
}

QString explainUndefinedToken(const QString &message, const PageDefines &defines)
{
    static const QRegularExpression undefined(QStringLiteral(
        R"((?:undefined macro\s+|[`'"‘])([A-Z][A-Z0-9_]+)(?:['"’]?\s+undeclared)?)"));
    const QRegularExpressionMatch m = undefined.match(message);
    if (!m.hasMatch()
        || !(message.contains(QLatin1StringView("undefined"))
             || message.contains(QLatin1StringView("undeclared"))))
        return message;
    const QString token = m.captured(1);
    if (defines.count(token))
        return message;
    return message
        + CoursePreludeWords::tr(" (%1 is never defined: if the page's JavaScript replaces it "
                                 "before compiling, give its value with --define %1=VALUE or "
                                 "the scene's \"defines\")")
              .arg(token);
}

} // namespace phonglab
