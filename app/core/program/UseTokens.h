#pragma once
// Internal to BindingsByUse*.cpp: one stage's tokens, their brackets, and
// the variables of a program a reference in them names. Both readers of a
// shader's use (what a uniform does; which term it scales) stand on it.
#include "core/program/GlslTokens.h"
#include "core/program/ShaderBindings.h"

#include <QByteArray>
#include <QString>

#include <string_view>
#include <vector>

namespace phonglab::usetokens {

// Bounds that keep arbitrary bytes from exhausting the time.
constexpr std::size_t kMaxUseTokens = 200000;
constexpr int kMaxFollow = 4; // locals followed back to what they were set from

QString toQString(std::string_view s);

class UseTokens
{
public:
    UseTokens(const QByteArray &code, const ProgramBindings &bindings);

    std::string_view text(int i) const { return i >= 0 && i < m_n ? m_tokens[i].text : ""; }
    bool is(int i, std::string_view t) const { return text(i) == t; }
    bool word(int i) const { return i >= 0 && i < m_n && m_tokens[i].word; }
    int line(int i) const { return i >= 0 && i < m_n ? m_tokens[i].line : 0; }
    int closeOf(int i) const { return i >= 0 && i < m_n && m_partner[i] >= 0 ? m_partner[i] : m_n; }
    int next(int i) const { return glsl::oneOf(text(i), {"(", "[", "{"}) ? closeOf(i) + 1 : i + 1; }
    // The end of one argument or operand list from `i`: the first `stop`
    // (or `,`, `;`, a closing bracket) at this bracket level.
    int until(int i, std::string_view stop) const;
    // The variables a reference starting at `i` names: `u`, `u[i]` (an
    // array, one variable), `s.member`, `s[k].member` (the member of light
    // k, or of every light for an index that is no number); a swizzle is
    // the vector's. `end` receives the token after it.
    std::vector<int> variablesAt(int i, int *end) const;
    // The variables the expression [begin, end) is, as a whole: a reference,
    // in parentheses, a constructor of one argument, or a local set from one.
    std::vector<int> referenceIn(int begin, int end, int depth = 0) const;
    // Where the value of the local `local` is given last before `before`
    // (`float n = EXPR;` or `n = EXPR;`): EXPR's first token, or -1.
    int initializerOf(std::string_view local, int before) const;
    // The name of the call whose parentheses hold token `k` directly, or -1.
    int enclosingCall(int k) const;

protected:
    const ProgramBindings &m_variables;
    std::vector<std::string_view> m_macroWords;
    std::vector<glsl::Token> m_tokens;
    int m_n = 0;
    std::vector<int> m_partner;
};

// The colours and gains that scale the ambient, diffuse or specular term,
// bound where no name did (BindingsByTerm.cpp); returns how many.
int bindTermFactors(ProgramBindings &bindings, const QByteArray &vertex,
                    const QByteArray &fragment);

} // namespace phonglab::usetokens
