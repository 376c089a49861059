#include "core/program/UseTokens.h"

#include <algorithm>

namespace phonglab::usetokens {

using namespace glsl;

QString toQString(std::string_view s)
{
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

UseTokens::UseTokens(const QByteArray &code, const ProgramBindings &bindings)
    : m_variables(bindings)
    , m_tokens(tokenize(code, m_macroWords))
    , m_n(int(m_tokens.size()))
{
    m_partner = bracketPartners(m_tokens);
}

int UseTokens::until(int i, std::string_view stop) const
{
    while (i < m_n && !is(i, stop) && !oneOf(text(i), {",", ";", ")", "]", "}"}))
        i = next(i);
    return i;
}

// The variables a reference starting at `i` names: `u`, `u[i]` (an array,
// one variable), `s.member`, `s[k].member` (the member of light k, or of
// every light for an index that is no number); a swizzle is the vector's.
std::vector<int> UseTokens::variablesAt(int i, int *end) const
{
    *end = i;
    if (!word(i) || isKeyword(text(i)) || isTypeName(text(i)))
        return {};
    const QString name = toQString(text(i));
    int j = i + 1;
    QString index;
    bool indexed = false;
    if (is(j, "[")) {
        indexed = true;
        const int close = closeOf(j);
        if (close == j + 2 && isDigit(text(j + 1)[0]))
            index = toQString(text(j + 1));
        j = close + 1;
    }
    QString member; // a struct's member, or a swizzle
    if (is(j, ".") && word(j + 1)) {
        member = toQString(text(j + 1));
        j += 2;
    }
    *end = j;
    std::vector<int> out;
    const auto &vars = m_variables.variables;
    if (!member.isEmpty()) {
        for (std::size_t v = 0; v < vars.size(); ++v) {
            const QString &n = vars[v].variable.name;
            const bool plain = !indexed && n == name + QLatin1Char('.') + member;
            const bool element = indexed && n.startsWith(name + QLatin1Char('['))
                && n.endsWith(QStringLiteral("].") + member)
                && (index.isEmpty() || n == QStringLiteral("%1[%2].%3").arg(name, index, member));
            if (plain || element)
                out.push_back(int(v));
        }
        if (!out.empty())
            return out;
    }
    for (std::size_t v = 0; v < vars.size(); ++v)
        if (vars[v].variable.name == name)
            out.push_back(int(v));
    if (out.empty())
        *end = i;
    return out;
}

// The variables the expression [begin, end) is, as a whole: a reference,
// in parentheses, a constructor of one argument (`float(n)`, `vec3(u)`), or
// a local set from one.
std::vector<int> UseTokens::referenceIn(int begin, int end, int depth) const
{
    while (end - begin >= 3 && is(begin + 1, "(") && closeOf(begin + 1) == end - 1
           && isTypeName(text(begin)))
        begin += 2, --end;
    while (end - begin >= 2 && is(begin, "(") && closeOf(begin) == end - 1)
        ++begin, --end;
    int after = begin;
    std::vector<int> vars = variablesAt(begin, &after);
    if (!vars.empty())
        return after == end ? vars : std::vector<int>();
    if (end == begin + 1 && word(begin) && depth < kMaxFollow) {
        const int init = initializerOf(text(begin), begin);
        if (init >= 0)
            return referenceIn(init, until(init, ";"), depth + 1);
    }
    return {};
}

// Where the value of the local `local` is given last before token `before`
// (`float n = EXPR;` or `n = EXPR;`): EXPR's first token, or -1.
int UseTokens::initializerOf(std::string_view local, int before) const
{
    for (int k = std::min(before, m_n) - 1; k > 0; --k)
        if (text(k) == local && is(k + 1, "=") && !is(k - 1, "."))
            return k + 2;
    return -1;
}

// The name of the call whose parentheses hold token `k` directly, or -1.
int UseTokens::enclosingCall(int k) const
{
    int depth = 0;
    for (int up = k - 1; up >= 0 && up > k - 64; --up) {
        if (oneOf(text(up), {")", "]"}))
            ++depth;
        else if (oneOf(text(up), {"(", "["}) && depth > 0)
            --depth;
        else if (is(up, "(") && word(up - 1))
            return up - 1;
        else if (oneOf(text(up), {";", "{", "}"}))
            return -1;
    }
    return -1;
}

} // namespace phonglab::usetokens
