#include "JsShaders.h"

#include <QHash>

#include <algorithm>

namespace phonglab {

namespace {

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
    bool isIdentifier(std::size_t i) const
    {
        return i < size() && m_tokens[i].kind == JsTokenKind::Identifier;
    }
    JsStringValue value(std::size_t i) const { return jsStringValue(m_js, m_tokens[i]); }
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
        if (!t.isLiteral(i))
            return std::nullopt;
        if (!first)
            append(out, separator);
        append(out, t.value(i));
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
        } else if (t.isLiteral(i)) {
            append(text, t.value(i));
            text.pieces = 1;
            text.quote = js[std::size_t(t[i].begin)];
            while (t.is(next, "+") && t.isLiteral(next + 1)) {
                append(text, t.value(next + 1));
                ++text.pieces;
                next += 2;
            }
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
