#include "HtmlShaders.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#include <gumbo.h>

#include <algorithm>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct HtmlShadersWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::HtmlShaders)
};

namespace {

QString attribute(const GumboElement &element, const char *name)
{
    const GumboAttribute *a = gumbo_get_attribute(&element.attributes, name);
    return a ? QString::fromUtf8(a->value).trimmed() : QString();
}

bool isJavaScriptType(const QString &type)
{
    const QString t = type.toLower();
    return t.isEmpty() || t == QLatin1String("text/javascript")
        || t == QLatin1String("application/javascript") || t == QLatin1String("module")
        || t == QLatin1String("text/ecmascript") || t == QLatin1String("application/ecmascript")
        || t == QLatin1String("text/babel") || t == QLatin1String("text/jsx");
}

// The raw bytes of an element's text, where gumbo saw them in the file.
struct RawText {
    qsizetype begin = -1;
    qsizetype end = -1;
};

RawText rawText(const GumboElement &element, const QByteArray &html)
{
    // Between the start tag's end and the end tag's start: what the file
    // holds, character references and all.
    RawText raw;
    if (element.original_tag.length == 0)
        return raw; // a tag the parser added: nothing of it is in the file
    const char *base = html.constData();
    raw.begin =
        qsizetype(element.original_tag.data - base) + qsizetype(element.original_tag.length);
    if (element.original_end_tag.length > 0) {
        raw.end = qsizetype(element.original_end_tag.data - base);
        return raw;
    }
    raw.end = raw.begin; // no end tag: the text children say how far it goes
    for (unsigned i = 0; i < element.children.length; ++i) {
        const auto *child = static_cast<const GumboNode *>(element.children.data[i]);
        if (child->type == GUMBO_NODE_TEXT || child->type == GUMBO_NODE_CDATA
            || child->type == GUMBO_NODE_WHITESPACE)
            raw.end = std::max(raw.end,
                               qsizetype(child->v.text.original_text.data - base)
                                   + qsizetype(child->v.text.original_text.length));
    }
    return raw;
}

// An HTML character reference at `i` ('&'): its text and length, or none.
std::optional<std::pair<QByteArray, qsizetype>> characterReference(const QByteArray &s, qsizetype i)
{
    const qsizetype semicolon = s.indexOf(';', i);
    if (semicolon < 0 || semicolon - i > 10)
        return std::nullopt;
    const QByteArray name = s.mid(i + 1, semicolon - i - 1);
    const qsizetype length = semicolon - i + 1;
    static const std::pair<const char *, const char *> named[] = {
        {"lt", "<"}, {"gt", ">"}, {"amp", "&"}, {"quot", "\""}, {"apos", "'"}, {"nbsp", " "}};
    for (const auto &[n, text] : named)
        if (name == n)
            return std::pair{QByteArray(text), length};
    if (name.startsWith('#')) {
        bool ok = false;
        const uint cp = name.startsWith("#x") || name.startsWith("#X") ? name.mid(2).toUInt(&ok, 16)
                                                                       : name.mid(1).toUInt(&ok);
        if (ok && cp > 0 && cp <= 0x10FFFF) {
            const char32_t c = cp;
            return std::pair{QString::fromUcs4(&c, 1).toUtf8(), length};
        }
    }
    return std::nullopt;
}

// A textarea's value: its raw text with character references read, the
// newline right after the start tag dropped (as HTML does).
FoundText textareaText(const QByteArray &html, const RawText &raw)
{
    FoundText text;
    qsizetype i = raw.begin;
    if (i < raw.end && html[i] == '\n')
        ++i;
    while (i < raw.end) {
        if (html[i] == '&') {
            if (const auto ref = characterReference(html, i)) {
                for (const char c : ref->first) {
                    text.value += c;
                    text.from.push_back(i);
                }
                i += ref->second;
                continue;
            }
        }
        text.value += html[i];
        text.from.push_back(i);
        ++i;
    }
    text.begin = raw.begin + (raw.begin < raw.end && html[raw.begin] == '\n' ? 1 : 0);
    text.end = raw.end;
    text.container = ShaderContainer::Textarea;
    return text;
}

void walk(const GumboNode *node, const QByteArray &html, std::vector<FoundText> &out,
          std::vector<RawText> *scripts)
{
    if (node->type != GUMBO_NODE_ELEMENT && node->type != GUMBO_NODE_TEMPLATE)
        return;
    const GumboElement &element = node->v.element;
    const RawText raw = rawText(element, html);
    if (element.tag == GUMBO_TAG_SCRIPT && raw.begin >= 0 && raw.end > raw.begin) {
        if (isJavaScriptType(attribute(element, "type"))) {
            if (scripts)
                scripts->push_back(raw);
            const auto js = foundInJs(html.mid(raw.begin, raw.end - raw.begin), raw.begin);
            out.insert(out.end(), js.begin(), js.end());
        } else {
            FoundText text;
            text.value = html.mid(raw.begin, raw.end - raw.begin);
            for (qsizetype i = raw.begin; i < raw.end; ++i)
                text.from.push_back(i);
            text.name = attribute(element, "id");
            text.begin = raw.begin;
            text.end = raw.end;
            text.container = ShaderContainer::ScriptElement;
            out.push_back(std::move(text));
        }
        return;
    }
    if (element.tag == GUMBO_TAG_TEXTAREA && raw.begin >= 0 && raw.end > raw.begin) {
        FoundText text = textareaText(html, raw);
        text.name = attribute(element, "id");
        out.push_back(std::move(text));
        return;
    }
    for (unsigned i = 0; i < element.children.length; ++i)
        walk(static_cast<const GumboNode *>(element.children.data[i]), html, out, scripts);
}

// Parses and walks `html`; the inline scripts' ranges go to `scripts`.
std::vector<FoundText> readHtml(const QByteArray &html, std::vector<RawText> *scripts)
{
    GumboOptions options = kGumboDefaultOptions;
    options.tab_stop = 1;
    options.max_errors = 100;
    GumboOutput *output =
        gumbo_parse_with_options(&options, html.constData(), std::size_t(html.size()));
    std::vector<FoundText> out;
    if (output) {
        walk(output->root, html, out, scripts);
        gumbo_destroy_output(&options, output);
    }
    return out;
}

} // namespace

std::vector<FoundText> shaderTextsInHtml(const QByteArray &html)
{
    return readHtml(html, nullptr);
}

std::vector<FoundText> foundInJs(const QByteArray &js, qsizetype base)
{
    const std::string_view view(js.constData(), std::size_t(js.size()));
    std::vector<FoundText> out;
    for (JsShaderText &t : shaderTextsInJs(view)) {
        FoundText text;
        text.value = std::move(t.value);
        text.from.reserve(t.from.size());
        for (const qsizetype at : t.from)
            text.from.push_back(at + base);
        text.name = t.name;
        text.begin = t.begin + base;
        text.end = t.end + base;
        // One literal: its inside is the text's place (the quotes stay).
        if (t.pieces == 1) {
            ++text.begin;
            --text.end;
            text.container =
                t.quote == '`' ? ShaderContainer::JsTemplate : ShaderContainer::JsString;
            text.quote = t.quote;
        } else {
            text.container = ShaderContainer::JsPieces;
        }
        out.push_back(std::move(text));
    }
    return out;
}

bool holdsShaderStrings(const QByteArray &file)
{
    // GLSL holds no quote or backtick outside comments: most shader files end here.
    if (!file.contains('`') && !file.contains('"') && !file.contains('\''))
        return false;
    for (const FoundText &text : foundInJs(file, 0))
        if (stageOfShaderText(text.value))
            return true;
    return false;
}

std::vector<JsProgramCall> programCallsInFile(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    const QByteArray file = f.readAll();
    std::vector<RawText> scripts;
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix.startsWith(QLatin1String("htm")) || suffix == QLatin1String("xhtml"))
        readHtml(file, &scripts);
    else
        scripts.push_back({0, file.size()});
    std::vector<JsProgramCall> calls;
    for (const RawText &script : scripts) {
        const QByteArray js = file.mid(script.begin, script.end - script.begin);
        for (JsProgramCall call : programCallsInJs({js.constData(), std::size_t(js.size())})) {
            for (JsShaderRef *ref : {&call.vertex, &call.fragment})
                if (ref->literalAt)
                    *ref->literalAt += script.begin;
            calls.push_back(std::move(call));
        }
    }
    return calls;
}

} // namespace phonglab
