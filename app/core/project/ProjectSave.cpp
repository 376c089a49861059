#include "ProjectSave.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QRegularExpression>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ProjectSaveWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ProjectSave)
};

QByteArray encodedShaderText(ShaderContainer container, char quote, const QByteArray &text)
{
    QByteArray out;
    out.reserve(text.size() + 16);
    switch (container) {
    case ShaderContainer::File:
    case ShaderContainer::ScriptElement:
    case ShaderContainer::JsPieces: return text;
    case ShaderContainer::Textarea:
        for (const char c : text)
            out += c == '&' ? QByteArray("&amp;")
                : c == '<'  ? QByteArray("&lt;")
                            : QByteArray(1, c);
        return out;
    case ShaderContainer::JsTemplate:
        for (qsizetype i = 0; i < text.size(); ++i) {
            const char c = text[i];
            if (c == '\\' || c == '`' || (c == '$' && i + 1 < text.size() && text[i + 1] == '{'))
                out += '\\';
            if (c == '\r') {
                out += "\\r";
                continue;
            }
            out += c;
        }
        return out;
    case ShaderContainer::JsString:
        for (const char c : text) {
            if (c == '\\' || c == quote)
                out += '\\';
            if (c == '\n')
                out += "\\n";
            else if (c == '\r')
                out += "\\r";
            else
                out += c;
        }
        return out;
    }
    return text;
}

namespace {

// Text HTML would not read back as the script element's whole content: what
// ends the element ("</script" and then a space, a slash or ">", any case),
// or "<!--", after which a script's parsing takes turns of its own.
bool breaksScriptElement(const QByteArray &text)
{
    static const QRegularExpression endTag(QStringLiteral("</script[\\t\\n\\f\\r />]"),
                                           QRegularExpression::CaseInsensitiveOption);
    return text.contains("<!--") || endTag.match(QString::fromUtf8(text)).hasMatch();
}

} // namespace

QString whyNotWritable(const ProjectShader &shader, const QByteArray &file)
{
    if (shader.container == ShaderContainer::ScriptElement && breaksScriptElement(shader.text))
        return ProjectSaveWords::tr("the script element holds \"<!--\" or \"</script\"");
    if (shader.container == ShaderContainer::JsPieces)
        return ProjectSaveWords::tr("the script builds the shader from several strings");
    if (encodedShaderText(shader.container, shader.quote, shader.text)
        != file.mid(shader.begin, shader.end - shader.begin))
        return shader.container == ShaderContainer::Textarea
            ? ProjectSaveWords::tr("the textarea writes its characters another way than & and < "
                                   "as references")
            : ProjectSaveWords::tr("the script writes the shader with escapes of its own");
    return {};
}

Result<QByteArray> withShaderText(const QByteArray &file, const ProjectShader &shader,
                                  const QByteArray &text)
{
    const QString name = QFileInfo(shader.file).fileName();
    if (!shader.writable)
        return fail(
            ProjectSaveWords::tr("%1: the shader %2 cannot be saved back into the file (%3); "
                                 "use Save As to write it to a file of its own")
                .arg(name, shader.key, shader.notWritable));
    if (shader.container == ShaderContainer::ScriptElement && breaksScriptElement(text))
        return fail(ProjectSaveWords::tr("%1: the shader %2 holds \"<!--\" or \"</script\", which "
                                         "would change where its script element ends; use Save As")
                        .arg(name, shader.key));
    if (shader.begin < 0 || shader.end > file.size() || shader.end < shader.begin)
        return fail(ProjectSaveWords::tr("%1 changed on disk; open it again").arg(name));
    return file.left(shader.begin) + encodedShaderText(shader.container, shader.quote, text)
        + file.mid(shader.end);
}

} // namespace phonglab
