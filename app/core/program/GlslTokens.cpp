#include "core/program/GlslTokens.h"

#include <QtGlobal>

#include <algorithm>

namespace phonglab::glsl {

bool oneOf(std::string_view word, Words words)
{
    return std::find(words.begin(), words.end(), word) != words.end();
}

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}
bool isWordStart(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool isWordChar(char c)
{
    return isWordStart(c) || isDigit(c);
}

// Whether `word` is one of the words of `list`, which has a space around each.
bool listed(std::string_view list, std::string_view word)
{
    for (std::size_t at = list.find(word); !word.empty() && at != std::string_view::npos;
         at = list.find(word, at + 1))
        if (at > 0 && list[at - 1] == ' ' && at + word.size() < list.size()
            && list[at + word.size()] == ' ')
            return true;
    return false;
}

bool isKeyword(std::string_view w)
{
    return listed(" if else for while do switch case default return break continue discard struct "
                  "precision true false ",
                  w);
}

bool isQualifier(std::string_view w)
{
    return listed(" const highp mediump lowp precise invariant flat smooth noperspective centroid ",
                  w);
}

// float, ivec3, mat4, dmat2x3: a constructor when called.
bool isTypeName(std::string_view w)
{
    if (oneOf(w, {"float", "int", "uint", "bool", "double"}))
        return true;
    if (w.size() > 3 && oneOf(w.substr(0, 1), {"i", "u", "b", "d"}))
        w.remove_prefix(1);
    const auto size = [](char c) { return c >= '2' && c <= '4'; };
    if (w.size() == 4 && w.starts_with("vec"))
        return size(w[3]);
    return w.starts_with("mat")
        && ((w.size() == 4 && size(w[3]))
            || (w.size() == 6 && size(w[3]) && w[4] == 'x' && size(w[5])));
}

// Built-ins that only read their arguments (modf and frexp write one: absent).
bool onlyReads(std::string_view f)
{
    return listed(" radians degrees sin cos tan asin acos atan pow exp log exp2 log2 sqrt "
                  "inversesqrt abs sign floor trunc round ceil fract mod min max clamp mix step "
                  "smoothstep length distance dot cross normalize faceforward reflect refract "
                  "transpose determinant inverse lessThan greaterThan equal notEqual any all not "
                  "texture texture2D textureCube textureLod texelFetch texture2DLod textureCubeLod "
                  "textureProj dFdx dFdy fwidth ",
                  f);
}

namespace {

// Where a preprocessor line ends: its '\n', unless a backslash continues it.
std::size_t directiveEnd(std::string_view s, std::size_t from)
{
    for (std::size_t e = s.find('\n', from);; e = s.find('\n', e + 1)) {
        if (e == std::string_view::npos)
            return s.size();
        const std::size_t last = e > 0 && s[e - 1] == '\r' ? e - 1 : e;
        if (last == 0 || s[last - 1] != '\\')
            return e;
    }
}

} // namespace

std::size_t tokenEnd(std::string_view s, std::size_t i)
{
    std::size_t e = i + 1;
    if (isDigit(s[i]) || (s[i] == '.' && e < s.size() && isDigit(s[e]))) { // 1.5e-3, 0x1Fu, .5
        while (e < s.size()
               && (isWordChar(s[e]) || s[e] == '.'
                   || ((s[e] == '-' || s[e] == '+') && (s[e - 1] == 'e' || s[e - 1] == 'E'))))
            ++e;
    } else if (isWordStart(s[i])) {
        while (e < s.size() && isWordChar(s[e]))
            ++e;
    } else {
        for (std::string_view op : {"<<=", ">>=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=",
                                    "++", "--", "==", "!=", "<=", ">=", "&&", "||", "^^"})
            if (s.substr(i, op.size()) == op)
                return i + op.size();
    }
    return e;
}

std::vector<Token> tokenize(const QByteArray &code, std::vector<std::string_view> &macroWords)
{
    std::vector<Token> out;
    const std::string_view s(code.constData(), std::size_t(code.size()));
    std::size_t i = 0;
    int line = 1;
    int column = 1;
    bool lineStart = true; // only blanks and comments so far on this line: # starts a directive
    const auto advance = [&](std::size_t to) {
        for (; i < to; ++i) {
            if (s[i] == '\n') {
                ++line;
                column = 1;
                lineStart = true;
            } else if ((uchar(s[i]) & 0xC0) != 0x80) { // UTF-8: one column a character
                ++column;
            }
        }
    };
    while (i < s.size()) {
        const std::string_view two = s.substr(i, 2);
        if (oneOf(s.substr(i, 1), {" ", "\t", "\r", "\n", "\f", "\v"})) {
            advance(i + 1);
        } else if (two == "//") {
            advance(std::min(s.find('\n', i), s.size()));
        } else if (two == "/*") {
            const std::size_t e = s.find("*/", i + 2);
            advance(e == std::string_view::npos ? s.size() : e + 2);
        } else if (s[i] == '#' && lineStart) {
            const std::size_t e = directiveEnd(s, i);
            for (std::size_t w = i; w < e; ++w)
                if (isWordStart(s[w]) && !isWordChar(s[w - 1]))
                    macroWords.push_back(s.substr(w, tokenEnd(s, w) - w));
            advance(e);
        } else {
            const std::size_t e = tokenEnd(s, i);
            out.push_back({isWordStart(s[i]), s.substr(i, e - i), line, column});
            lineStart = false;
            advance(e);
        }
    }
    return out;
}

std::vector<int> bracketPartners(const std::vector<Token> &tokens)
{
    std::vector<int> partner(tokens.size(), -1);
    std::vector<int> open;
    for (int i = 0; i < int(tokens.size()); ++i) {
        const std::string_view t = tokens[std::size_t(i)].text;
        if (oneOf(t, {"(", "[", "{"})) {
            open.push_back(i);
        } else if (oneOf(t, {")", "]", "}"}) && !open.empty()) {
            const char expected = t == ")" ? '(' : t == "]" ? '[' : '{';
            if (tokens[std::size_t(open.back())].text[0] != expected)
                continue;
            partner[std::size_t(i)] = open.back();
            partner[std::size_t(open.back())] = i;
            open.pop_back();
        }
    }
    return partner;
}

} // namespace phonglab::glsl
