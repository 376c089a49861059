#include "JsShaders.h"

#include <QHash>
#include <QRegularExpression>

#include <algorithm>
#include <cctype>

namespace phonglab {

namespace {

// Names an expression reads through or converts with, which say nothing of
// what its value is (`this.n`, `String(n)`, `n.toFixed(1)`).
bool isHolderOrConversion(std::string_view word)
{
    for (const char *w : {"this", "window", "self", "globalThis", "String", "Number", "parseInt",
                          "parseFloat", "toString", "toFixed", "Math", "round", "floor"})
        if (word == w)
            return true;
    return false;
}

// "numLights" and "num_lights" both NUM_LIGHTS: the way a page's tokens are written.
QByteArray upperSnake(std::string_view word)
{
    QByteArray out;
    for (std::size_t k = 0; k < word.size(); ++k) {
        const unsigned char c = static_cast<unsigned char>(word[k]);
        const unsigned char before = k > 0 ? static_cast<unsigned char>(word[k - 1]) : 0;
        if (std::isupper(c) && (std::islower(before) || std::isdigit(before)))
            out += '_';
        if (std::isalnum(c))
            out += char(std::toupper(c));
        else if (c == '_' || c == '$')
            out += '_';
    }
    return out;
}

// A name GLSL takes: no run of underscores (reserved) and none at either
// end, no digit first, no GL_ first (reserved), not too long.
QByteArray validGlslName(const QByteArray &name)
{
    QByteArray out;
    for (const char c : name.left(64))
        if (c != '_' || (!out.isEmpty() && !out.endsWith('_')))
            out += c;
    while (out.endsWith('_'))
        out.chop(1);
    if (out.isEmpty())
        return "JS_VALUE";
    if (std::isdigit(static_cast<unsigned char>(out[0])) || out.startsWith("GL_"))
        out.prepend("JS_");
    return out;
}

class Tokens
{
public:
    explicit Tokens(std::string_view js)
        : m_js(js)
        , m_tokens(scanJs(js))
    {
    }
    std::size_t size() const { return m_tokens.size(); }
    const JsToken &operator[](std::size_t i) const { return m_tokens[i]; }
    std::string_view text(std::size_t i) const
    {
        if (i >= m_tokens.size())
            return {};
        const JsToken &t = m_tokens[i];
        return m_js.substr(std::size_t(t.begin), std::size_t(t.end - t.begin));
    }
    bool is(std::size_t i, std::string_view s) const { return i < size() && text(i) == s; }
    bool isLiteral(std::size_t i) const
    {
        return i < size()
            && (m_tokens[i].kind == JsTokenKind::String
                || m_tokens[i].kind == JsTokenKind::Template)
            && !m_tokens[i].hasSubstitution;
    }
    // A template literal with ${...}: a piece whose substitutions the page fills in.
    bool isTemplateWithSubstitution(std::size_t i) const
    {
        return i < size() && m_tokens[i].kind == JsTokenKind::Template
            && m_tokens[i].hasSubstitution;
    }
    bool isPiece(std::size_t i) const { return isLiteral(i) || isTemplateWithSubstitution(i); }
    bool isIdentifier(std::size_t i) const
    {
        return i < size() && m_tokens[i].kind == JsTokenKind::Identifier;
    }
    std::string_view js() const { return m_js; }
    JsStringValue value(std::size_t i) const { return jsStringValue(m_js, m_tokens[i]); }
    JsTemplateParts parts(std::size_t i) const { return jsTemplateParts(m_js, m_tokens[i]); }
    QString string(std::size_t i) const { return QString::fromUtf8(value(i).value); }
    // The index of the bracket closing the one at `open`, or size().
    std::size_t closing(std::size_t open) const
    {
        int depth = 0;
        for (std::size_t i = open; i < size(); ++i) {
            const std::string_view t = text(i);
            if (t == "(" || t == "[" || t == "{")
                ++depth;
            else if ((t == ")" || t == "]" || t == "}") && --depth == 0)
                return i;
        }
        return size();
    }

private:
    std::string_view m_js;
    std::vector<JsToken> m_tokens;
};

void append(JsShaderText &out, const JsStringValue &piece)
{
    out.value += piece.value;
    out.from.insert(out.from.end(), piece.from.begin(), piece.from.end());
}

// Whether the text's last line defines the macro `name` (`#define N ` before
// the value `n`): its placeholder may not be N too, since `#define N N`
// clashes with the `--define N=3` that would give it.
bool definesMacroNamed(const QByteArray &value, const QByteArray &name)
{
    static const QRegularExpression define(QStringLiteral("^\\s*#\\s*define\\s+(\\w+)\\W"));
    const QRegularExpressionMatch m =
        define.match(QString::fromUtf8(value.mid(value.lastIndexOf('\n') + 1)));
    return m.hasMatch() && m.captured(1).toUtf8() == name;
}

// The placeholder for the JavaScript expression [begin, end) of the scanned
// text, appended: every byte of it comes from the expression's first, so a
// line that starts with it starts where the expression does.
void appendPlaceholder(const Tokens &t, qsizetype begin, qsizetype end, JsShaderText &out)
{
    const std::string_view js = t.js();
    qsizetype at = begin;
    while (at < end && std::isspace(static_cast<unsigned char>(js[std::size_t(at)])))
        ++at;
    QByteArray name = jsPlaceholderName(js.substr(std::size_t(begin), std::size_t(end - begin)));
    if (definesMacroNamed(out.value, name))
        name += "_VALUE";
    out.value += name;
    out.from.insert(out.from.end(), std::size_t(name.size()), at < end ? at : begin);
}

// A literal piece, or a template literal with its substitutions read as
// placeholders.
void appendPiece(const Tokens &t, std::size_t i, JsShaderText &out)
{
    if (t.isLiteral(i)) {
        append(out, t.value(i));
        ++out.pieces;
        return;
    }
    const JsTemplateParts template_ = t.parts(i);
    for (std::size_t k = 0; k < template_.parts.size(); ++k) {
        append(out, template_.parts[k]);
        if (k < template_.substitutions.size())
            appendPlaceholder(t, template_.substitutions[k].first,
                              template_.substitutions[k].second, out);
    }
    out.pieces += int(template_.parts.size());
}

constexpr std::size_t kMaxExpressionTokens = 64;

bool endsOperand(const Tokens &t, std::size_t i)
{
    const JsTokenKind kind = t[i].kind;
    return kind != JsTokenKind::Punctuator || t.is(i, ")") || t.is(i, "]");
}

// The expression that starts at token `i` and is followed by `+` and another
// piece (`this.num_lights` in `'lights[' + this.num_lights + '];'`): the index
// of that `+`. None where the expression ends the concatenation instead (at
// `;` `,` `)`, a `?`, an `=`, or a name right after an operand: a statement
// that has no semicolon).
std::optional<std::size_t> expressionBeforePiece(const Tokens &t, std::size_t i)
{
    int depth = 0;
    for (std::size_t k = i; k < t.size() && k < i + kMaxExpressionTokens; ++k) {
        const std::string_view s = t.text(k);
        if (depth == 0) {
            if (s == "+" && k > i && t.isPiece(k + 1))
                return k;
            if (s == ";" || s == "," || s == "=" || s == ":" || s == "?" || s == "{" || s == ")"
                || s == "]" || s == "}")
                return std::nullopt;
            if (k > i && endsOperand(t, k - 1) && t[k].kind != JsTokenKind::Punctuator)
                return std::nullopt;
        }
        if (s == "(" || s == "[" || s == "{")
            ++depth;
        else if (s == ")" || s == "]" || s == "}")
            --depth;
    }
    return std::nullopt;
}

// The pieces joined by `+` from piece `i` on, an expression between two of
// them read as its placeholder; the index past the last piece.
std::size_t concatenation(const Tokens &t, std::size_t i, JsShaderText &out)
{
    appendPiece(t, i, out);
    std::size_t next = i + 1;
    while (t.is(next, "+")) {
        if (t.isPiece(next + 1)) {
            appendPiece(t, next + 1, out);
            next += 2;
            continue;
        }
        const std::optional<std::size_t> plus = expressionBeforePiece(t, next + 1);
        if (!plus)
            break;
        appendPlaceholder(t, t[next + 1].begin, t[*plus - 1].end, out);
        appendPiece(t, *plus + 1, out);
        next = *plus + 2;
    }
    return next;
}

// `[ 'a', 'b' ].join('\n')` at `open` (the bracket): its value, and the
// index past the join's closing parenthesis.
std::optional<std::size_t> arrayJoin(const Tokens &t, std::size_t open, JsShaderText &out)
{
    const std::size_t close = t.closing(open);
    if (close >= t.size() || !t.is(close + 1, ".") || !t.is(close + 2, "join")
        || !t.is(close + 3, "(") || !t.isLiteral(close + 4) || !t.is(close + 5, ")"))
        return std::nullopt;
    const JsStringValue separator = t.value(close + 4);
    bool first = true;
    for (std::size_t i = open + 1; i < close; ++i) {
        if (t.is(i, ","))
            continue;
        if (!t.isPiece(i))
            return std::nullopt;
        if (!first)
            append(out, separator);
        appendPiece(t, i, out);
        first = false;
    }
    return close + 6;
}

// The name a value at token `start` is given: `name = `, `name: `, `"name": `.
QString assignedName(const Tokens &t, std::size_t start)
{
    if (start < 2)
        return {};
    const std::size_t op = start - 1;
    if ((t.is(op, "=") || t.is(op, ":")) && (t.isIdentifier(op - 1) || t.isLiteral(op - 1)))
        return t.isLiteral(op - 1) ? t.string(op - 1) : QString::fromUtf8(t.text(op - 1));
    return {};
}

// What one argument names: a string, the last name of a chain
// (`shaders.vs` is "vs"), the id in document.getElementById("id"), the path
// in require("text!path"), or a literal written in place.
JsShaderRef refAt(const Tokens &t, std::size_t begin, std::size_t end)
{
    JsShaderRef ref;
    for (std::size_t i = begin; i < end; ++i) {
        if (t.is(i, "getElementById") || t.is(i, "querySelector") || t.is(i, "require")
            || t.is(i, "fetch")) {
            if (t.is(i + 1, "(") && t.isLiteral(i + 2)) {
                QString name = t.string(i + 2);
                if (name.startsWith(QLatin1Char('#')))
                    name.remove(0, 1);
                if (name.startsWith(QStringLiteral("text!")))
                    name.remove(0, 5);
                ref.name = name;
                return ref;
            }
        }
    }
    if (t.isTemplateWithSubstitution(begin)) {
        JsShaderText text;
        appendPiece(t, begin, text);
        if (text.value.contains("main"))
            ref.literalAt = t[begin].begin;
        return ref; // a name computed by the page names nothing here
    }
    if (t.isLiteral(begin)) {
        const JsStringValue v = t.value(begin);
        if (v.value.contains("main"))
            ref.literalAt = t[begin].begin;
        else
            ref.name = QString::fromUtf8(v.value);
        return ref;
    }
    // The last identifier before a property that reads a text.
    for (std::size_t i = begin; i < end; ++i)
        if (t.isIdentifier(i)) {
            const std::string_view word = t.text(i);
            if (word != "textContent" && word != "text" && word != "innerHTML"
                && word != "innerText" && word != "value" && word != "this")
                ref.name = QString::fromUtf8(word);
        }
    return ref;
}

// The arguments of the call whose parenthesis opens at `open`, split at
// top-level commas: [begin, end) token ranges.
std::vector<std::pair<std::size_t, std::size_t>> arguments(const Tokens &t, std::size_t open)
{
    std::vector<std::pair<std::size_t, std::size_t>> args;
    const std::size_t close = t.closing(open);
    std::size_t start = open + 1;
    int depth = 0;
    for (std::size_t i = open + 1; i <= close && i < t.size(); ++i) {
        const std::string_view s = t.text(i);
        if (s == "(" || s == "[" || s == "{")
            ++depth;
        else if (s == ")" || s == "]" || s == "}")
            --depth;
        if ((s == "," && depth == 0) || i == close) {
            if (i > start)
                args.emplace_back(start, i);
            start = i + 1;
        }
    }
    return args;
}

// `{ vertexShader: A, fragmentShader: B }` at `open`.
std::optional<JsProgramCall> materialCall(const Tokens &t, std::size_t open)
{
    if (!t.is(open, "{"))
        return std::nullopt;
    JsProgramCall call;
    bool vertex = false, fragment = false;
    for (const auto &[begin, end] : arguments(t, open)) {
        if (!t.is(begin + 1, ":"))
            continue;
        const QString key = t.isLiteral(begin) ? t.string(begin) : QString::fromUtf8(t.text(begin));
        if (key == QLatin1String("vertexShader")) {
            call.vertex = refAt(t, begin + 2, end);
            vertex = true;
        } else if (key == QLatin1String("fragmentShader")) {
            call.fragment = refAt(t, begin + 2, end);
            fragment = true;
        }
    }
    if (!vertex || !fragment)
        return std::nullopt;
    return call;
}

} // namespace

QByteArray jsPlaceholderName(std::string_view expression)
{
    std::vector<std::string_view> words;
    for (const JsToken &token : scanJs(expression)) {
        if (token.kind != JsTokenKind::Identifier)
            continue;
        const std::string_view word =
            expression.substr(std::size_t(token.begin), std::size_t(token.end - token.begin));
        if (!isHolderOrConversion(word))
            words.push_back(word);
    }
    QByteArray name;
    if (!words.empty()) {
        name = upperSnake(words.back());
        if ((words.back() == "length" || words.back() == "size") && words.size() > 1)
            name = upperSnake(words[words.size() - 2]) + '_' + name;
    }
    return validGlslName(name);
}

std::vector<JsShaderText> shaderTextsInJs(std::string_view js)
{
    const Tokens t(js);
    std::vector<JsShaderText> found;
    for (std::size_t i = 0; i < t.size();) {
        JsShaderText text;
        std::size_t next = i + 1;
        if (t.is(i, "[")) {
            const std::optional<std::size_t> past = arrayJoin(t, i, text);
            if (!past) {
                ++i;
                continue;
            }
            next = *past;
            text.pieces = 2; // an array joined: written back as one text, never
        } else if (t.isPiece(i)) {
            text.quote = js[std::size_t(t[i].begin)];
            next = concatenation(t, i, text);
        } else {
            ++i;
            continue;
        }
        if (text.value.contains("main")) {
            text.name = assignedName(t, i);
            text.begin = t[i].begin;
            text.end = t[next - 1].end;
            found.push_back(std::move(text));
        }
        i = next;
    }
    return found;
}

std::vector<JsProgramCall> programCallsInJs(std::string_view js)
{
    const Tokens t(js);
    std::vector<JsProgramCall> calls;
    // `vs = createShader(gl, gl.VERTEX_SHADER, vsSource)`: vs stands for vsSource.
    QHash<QString, QString> holds;
    for (std::size_t i = 0; i + 3 < t.size(); ++i) {
        if (!t.isIdentifier(i) || !t.is(i + 1, "="))
            continue;
        for (const char *maker : {"createShader", "compileShader", "loadShader", "getShader",
                                  "makeShader", "buildShader"}) {
            std::size_t f = i + 2;
            while (f < t.size() && (t.isIdentifier(f) || t.is(f, ".")) && !t.is(f, maker))
                ++f;
            if (t.is(f, maker) && t.is(f + 1, "(")) {
                const auto args = arguments(t, f + 1);
                if (!args.empty()) {
                    const JsShaderRef source = refAt(t, args.back().first, args.back().second);
                    if (!source.name.isEmpty())
                        holds.insert(QString::fromUtf8(t.text(i)), source.name);
                }
            }
        }
    }
    const auto follow = [&](JsShaderRef ref) {
        for (int hops = 0; hops < 4 && holds.contains(ref.name); ++hops)
            ref.name = holds.value(ref.name);
        return ref;
    };
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
        if (!t.isIdentifier(i) || !t.is(i + 1, "("))
            continue;
        const std::string_view name = t.text(i);
        const auto args = arguments(t, i + 1);
        std::optional<JsProgramCall> call;
        if ((name == "ShaderMaterial" || name == "RawShaderMaterial") && !args.empty()) {
            call = materialCall(t, args.front().first);
        } else if ((name == "createProgramFromScripts" || name == "createProgramFromSources"
                    || name == "createProgramInfo")
                   && args.size() >= 2 && t.is(args[1].first, "[")) {
            const auto inner = arguments(t, args[1].first);
            if (inner.size() >= 2)
                call = JsProgramCall{refAt(t, inner[0].first, inner[0].second),
                                     refAt(t, inner[1].first, inner[1].second)};
        } else if ((name == "initShaders" || name == "initShaderProgram" || name == "createProgram"
                    || name == "linkProgram" || name == "makeProgram")
                   && args.size() == 3) {
            call = JsProgramCall{refAt(t, args[1].first, args[1].second),
                                 refAt(t, args[2].first, args[2].second)};
        }
        if (call && (!call->vertex.name.isEmpty() || call->vertex.literalAt)
            && (!call->fragment.name.isEmpty() || call->fragment.literalAt))
            calls.push_back({follow(call->vertex), follow(call->fragment)});
    }
    return calls;
}

} // namespace phonglab
