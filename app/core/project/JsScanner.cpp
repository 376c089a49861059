#include "JsScanner.h"

#include <cctype>

namespace phonglab {

namespace {

bool isIdentStart(unsigned char c)
{
    return std::isalpha(c) || c == '_' || c == '$' || c >= 0x80;
}

bool isIdentChar(unsigned char c)
{
    return isIdentStart(c) || std::isdigit(c);
}

// After these a slash starts a regex literal, not a division.
bool regexMayFollow(std::string_view js, const std::vector<JsToken> &tokens)
{
    if (tokens.empty())
        return true;
    const JsToken &last = tokens.back();
    const std::string_view text =
        js.substr(std::size_t(last.begin), std::size_t(last.end - last.begin));
    switch (last.kind) {
    case JsTokenKind::Number:
    case JsTokenKind::String:
    case JsTokenKind::Template:
    case JsTokenKind::Regex: return false;
    case JsTokenKind::Identifier:
        for (const char *word : {"return", "typeof", "instanceof", "in", "of", "new", "delete",
                                 "void", "throw", "case", "do", "else", "yield", "await"})
            if (text == word)
                return true;
        return false;
    case JsTokenKind::Punctuator: return text != ")" && text != "]" && text != "}";
    }
    return true;
}

// Past a quoted string starting at `i` (the quote): at the closing quote's
// successor, or at a line end (an unterminated string ends there).
std::size_t skipString(std::string_view js, std::size_t i)
{
    const char quote = js[i++];
    while (i < js.size()) {
        const char c = js[i];
        if (c == '\\') {
            i += 2;
            continue;
        }
        if (c == quote)
            return i + 1;
        if (c == '\n')
            return i;
        ++i;
    }
    return js.size();
}

std::size_t skipRegex(std::string_view js, std::size_t i)
{
    bool inClass = false;
    for (++i; i < js.size(); ++i) {
        const char c = js[i];
        if (c == '\\') {
            ++i;
            continue;
        }
        if (c == '\n')
            return i;
        if (c == '[')
            inClass = true;
        else if (c == ']')
            inClass = false;
        else if (c == '/' && !inClass) {
            ++i;
            while (i < js.size() && isIdentChar(static_cast<unsigned char>(js[i])))
                ++i; // flags
            return i;
        }
    }
    return js.size();
}

std::size_t skipTemplate(std::string_view js, std::size_t i, bool *substitution);

// Past the code of a ${...} substitution starting at `i` (after the brace):
// at the successor of its closing brace.
std::size_t skipSubstitution(std::string_view js, std::size_t i)
{
    int depth = 0;
    while (i < js.size()) {
        const char c = js[i];
        if (c == '\'' || c == '"') {
            i = skipString(js, i);
        } else if (c == '`') {
            bool inner = false;
            i = skipTemplate(js, i, &inner);
        } else if (c == '/' && i + 1 < js.size() && (js[i + 1] == '/' || js[i + 1] == '*')) {
            const std::size_t end = js[i + 1] == '/' ? js.find('\n', i) : js.find("*/", i + 2);
            i = end == std::string_view::npos ? js.size() : end + (js[i + 1] == '*' ? 2 : 0);
        } else {
            if (c == '{')
                ++depth;
            if (c == '}' && depth-- == 0)
                return i + 1;
            ++i;
        }
    }
    return js.size();
}

std::size_t skipTemplate(std::string_view js, std::size_t i, bool *substitution)
{
    for (++i; i < js.size();) {
        const char c = js[i];
        if (c == '\\') {
            i += 2;
            continue;
        }
        if (c == '`')
            return i + 1;
        if (c == '$' && i + 1 < js.size() && js[i + 1] == '{') {
            *substitution = true;
            i = skipSubstitution(js, i + 2);
            continue;
        }
        ++i;
    }
    return js.size();
}

int hexValue(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

void appendCodePoint(JsStringValue &out, char32_t cp, qsizetype from)
{
    const QByteArray bytes = QString::fromUcs4(&cp, 1).toUtf8();
    for (const char b : bytes) {
        out.value += b;
        out.from.push_back(from);
    }
}

// One escape sequence at `i` (the backslash); returns the index after it.
std::size_t readEscape(std::string_view js, std::size_t i, std::size_t end, JsStringValue &out)
{
    const qsizetype at = qsizetype(i);
    if (i + 1 >= end)
        return end;
    const char c = js[i + 1];
    i += 2;
    switch (c) {
    case 'n': appendCodePoint(out, '\n', at); return i;
    case 't': appendCodePoint(out, '\t', at); return i;
    case 'r': appendCodePoint(out, '\r', at); return i;
    case 'b': appendCodePoint(out, '\b', at); return i;
    case 'f': appendCodePoint(out, '\f', at); return i;
    case 'v': appendCodePoint(out, '\v', at); return i;
    case '0': appendCodePoint(out, 0, at); return i;
    case '\r': return i < end && js[i] == '\n' ? i + 1 : i; // a line continuation
    case '\n': return i;
    case 'x':
        if (i + 1 < end && hexValue(js[i]) >= 0 && hexValue(js[i + 1]) >= 0) {
            appendCodePoint(out, char32_t(hexValue(js[i]) * 16 + hexValue(js[i + 1])), at);
            return i + 2;
        }
        appendCodePoint(out, 'x', at);
        return i;
    case 'u': {
        char32_t cp = 0;
        if (i < end && js[i] == '{') {
            std::size_t j = i + 1;
            while (j < end && hexValue(js[j]) >= 0 && cp <= 0x10FFFF)
                cp = cp * 16 + char32_t(hexValue(js[j++]));
            if (j < end && js[j] == '}' && cp <= 0x10FFFF) {
                appendCodePoint(out, cp, at);
                return j + 1;
            }
        } else if (i + 3 < end) {
            bool ok = true;
            for (std::size_t k = 0; k < 4; ++k)
                ok = ok && hexValue(js[i + k]) >= 0;
            if (ok) {
                for (std::size_t k = 0; k < 4; ++k)
                    cp = cp * 16 + char32_t(hexValue(js[i + k]));
                appendCodePoint(out, cp, at);
                return i + 4;
            }
        }
        appendCodePoint(out, 'u', at);
        return i;
    }
    default:
        out.value += c; // \\ \' \" \` \$ and any other character stand for themselves
        out.from.push_back(at);
        return i;
    }
}

// The value of a literal's text [i, end), inside its quotes: escapes
// resolved, a template's CR LF read as LF; known from here on.
void readValue(std::string_view js, std::size_t i, std::size_t end, bool isTemplate,
               JsStringValue &out)
{
    while (i < end) {
        const char c = js[i];
        if (c == '\\') {
            i = readEscape(js, i, end, out);
            continue;
        }
        if (c == '\r' && isTemplate) {
            if (i + 1 < end && js[i + 1] == '\n')
                ++i;
            out.value += '\n';
            out.from.push_back(qsizetype(i));
            ++i;
            continue;
        }
        out.value += c;
        out.from.push_back(qsizetype(i));
        ++i;
    }
    out.known = true;
}

} // namespace

std::vector<JsToken> scanJs(std::string_view js)
{
    std::vector<JsToken> tokens;
    std::size_t i = 0;
    while (i < js.size()) {
        const unsigned char c = static_cast<unsigned char>(js[i]);
        if (std::isspace(c)) {
            ++i;
            continue;
        }
        if (c == '/' && i + 1 < js.size() && js[i + 1] == '/') {
            const std::size_t end = js.find('\n', i);
            i = end == std::string_view::npos ? js.size() : end;
            continue;
        }
        if (c == '/' && i + 1 < js.size() && js[i + 1] == '*') {
            const std::size_t end = js.find("*/", i + 2);
            i = end == std::string_view::npos ? js.size() : end + 2;
            continue;
        }
        // An HTML comment opener at a line's start is a line comment in a script.
        if (js.substr(i, 4) == "<!--") {
            const std::size_t end = js.find('\n', i);
            i = end == std::string_view::npos ? js.size() : end;
            continue;
        }
        JsToken token;
        token.begin = qsizetype(i);
        if (c == '\'' || c == '"') {
            token.kind = JsTokenKind::String;
            i = skipString(js, i);
        } else if (c == '`') {
            token.kind = JsTokenKind::Template;
            i = skipTemplate(js, i, &token.hasSubstitution);
        } else if (c == '/' && regexMayFollow(js, tokens)) {
            token.kind = JsTokenKind::Regex;
            i = skipRegex(js, i);
        } else if (isIdentStart(c)) {
            token.kind = JsTokenKind::Identifier;
            while (i < js.size() && isIdentChar(static_cast<unsigned char>(js[i])))
                ++i;
        } else if (std::isdigit(c)
                   || (c == '.' && i + 1 < js.size()
                       && std::isdigit(static_cast<unsigned char>(js[i + 1])))) {
            token.kind = JsTokenKind::Number;
            while (i < js.size()
                   && (std::isalnum(static_cast<unsigned char>(js[i])) || js[i] == '.'
                       || js[i] == '_'))
                ++i;
        } else {
            token.kind = JsTokenKind::Punctuator;
            ++i;
        }
        token.end = qsizetype(i);
        tokens.push_back(token);
    }
    return tokens;
}

JsStringValue jsStringValue(std::string_view js, const JsToken &literal)
{
    JsStringValue out;
    if ((literal.kind != JsTokenKind::String && literal.kind != JsTokenKind::Template)
        || literal.hasSubstitution || literal.end - literal.begin < 2)
        return out;
    const std::size_t end = std::size_t(literal.end) - 1; // the closing quote
    const char quote = js[std::size_t(literal.begin)];
    if (js[end] != quote)
        return out; // unterminated
    readValue(js, std::size_t(literal.begin) + 1, end, literal.kind == JsTokenKind::Template, out);
    return out;
}

JsTemplateParts jsTemplateParts(std::string_view js, const JsToken &literal)
{
    JsTemplateParts out;
    if (literal.kind != JsTokenKind::Template || literal.end - literal.begin < 2
        || js[std::size_t(literal.end) - 1] != '`')
        return out;
    const std::size_t end = std::size_t(literal.end) - 1; // the closing backtick
    std::size_t partBegin = std::size_t(literal.begin) + 1;
    std::vector<JsStringValue> parts;
    std::vector<std::pair<qsizetype, qsizetype>> substitutions;
    for (std::size_t i = partBegin; i < end;) {
        if (js[i] == '\\') {
            i += 2; // \${ is text, not a substitution
            continue;
        }
        if (js[i] != '$' || i + 1 >= end || js[i + 1] != '{') {
            ++i;
            continue;
        }
        // The scanner found the same closing brace: the token ends after it.
        const std::size_t close = skipSubstitution(js, i + 2);
        if (close > end)
            return out; // a substitution that never closes: nothing is known
        parts.emplace_back();
        readValue(js, partBegin, i, true, parts.back());
        substitutions.emplace_back(qsizetype(i + 2), qsizetype(close - 1));
        partBegin = i = close;
    }
    parts.emplace_back();
    readValue(js, partBegin, end, true, parts.back());
    out.parts = std::move(parts);
    out.substitutions = std::move(substitutions);
    return out;
}

} // namespace phonglab
