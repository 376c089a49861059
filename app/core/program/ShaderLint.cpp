#include "core/program/ShaderLint.h"

#include "core/program/ShaderLintWalk.h"

#include <algorithm>
#include <tuple>

namespace phonglab {

namespace lint {

Lint::Lint(const QByteArray &code)
    : tokens(tokenize(code, macroWords))
    , n(int(tokens.size()))
{
    matchBrackets();
    readTopLevel();
    for (Function &f : functions)
        f.mayWriteOutputs = mayWriteOutputs(f);
}

std::vector<LintFinding> Lint::run()
{
    // A macro that calls a helper (`#define SHADE shade()`) may set an output unseen.
    const bool hiddenCalls = std::any_of(functions.begin(), functions.end(), [&](auto &f) {
        return std::find(macroWords.begin(), macroWords.end(), f.name) != macroWords.end();
    });
    for (const Function &f : functions) {
        vars.clear();
        if (f.name == "main") // outputs are checked in main() only
            for (int o : outputs)
                declare(o, hiddenCalls ? State::Maybe : State::Unset, true);
        for (int p : f.parameters)
            declare(p, State::Set, false);
        if (f.body >= 0)
            block(f.body, n);
    }
    std::sort(found.begin(), found.end(), [](const LintFinding &a, const LintFinding &b) {
        return std::pair(a.line, a.column) < std::pair(b.line, b.column);
    });
    return gaveUp ? std::vector<LintFinding>() : found;
}

void Lint::matchBrackets()
{
    partner.assign(n, -1);
    enclosing.assign(n, -1);
    argument.assign(n, 0);
    const std::string_view pairs = "()[]{}";
    std::vector<std::pair<int, int>> open; // bracket, commas so far
    for (int i = 0; i < n; ++i) {
        if (!open.empty())
            std::tie(enclosing[i], argument[i]) = open.back();
        const std::string_view t = text(i);
        if (opens(i)) {
            open.push_back({i, 0});
            partner[i] = n;
        } else if (t == "," && !open.empty()) {
            ++open.back().second;
        } else if (!open.empty() && oneOf(t, {")", "]", "}"})
                   && text(open.back().first)[0] == pairs[pairs.find(t[0]) - 1]) {
            partner[i] = open.back().first;
            partner[open.back().first] = i;
            open.pop_back();
        }
    }
}

// Functions, prototypes, struct names and `out` variables.
void Lint::readTopLevel()
{
    for (int i = 0, k = 0; i < n; i = k + 1) {
        for (k = i; k < n && !is(k, ";") && !is(k, "{") && !is(k, "}");)
            k = is(k, "(") || is(k, "[") ? closeOf(k) + 1 : k + 1;
        const int open = is(k - 1, ")") ? partner[k - 1] : -1;
        const bool function = open > i && tok(open - 1).word;
        if (is(k, "{") && function) {
            addFunction(open, k);
            k = closeOf(k);
        } else if (is(k, "{")) { // a struct or an interface block, and its declarators
            for (int s = i; s < k; ++s)
                if (is(s, "struct") && tok(s + 1).word)
                    structs.push_back(text(s + 1));
            k = until(closeOf(k) + 1, n, ";");
        } else if (is(k, ";") && function && until(i, open, "=") == open) {
            addFunction(open, -1);
        } else if (is(k, ";")) {
            declareOutputs(i, k);
        }
    }
}

// `vec3 shade(in vec3 n, out float d)`: which arguments it writes, its
// parameters' names.
void Lint::addFunction(int open, int body)
{
    Function f{text(open - 1), body, {}, {}};
    for (int k = open + 1, e = 0; k < closeOf(open); k = e + 1) {
        e = until(k, closeOf(open), ",");
        bool writes = false;
        int name = -1;
        for (int m = k; m < e; m = is(m, "[") ? closeOf(m) + 1 : m + 1) {
            writes = writes || is(m, "out") || is(m, "inout");
            name = tok(m).word ? m : name;
        }
        f.writes.push_back(writes);
        if (name >= 0)
            f.parameters.push_back(name);
    }
    functions.push_back(f);
}

// Whether a call of f may set an output: its body names one, or calls
// another function of the shader (not followed further).
bool Lint::mayWriteOutputs(const Function &f) const
{
    for (int k = f.body + 1; f.body >= 0 && k < closeOf(f.body); ++k) {
        const auto named = [&](int o) { return is(k, text(o)); };
        if (std::any_of(outputs.begin(), outputs.end(), named)
            || (tok(k).word && is(k + 1, "(") && function(text(k)) && !outputs.empty()))
            return true;
    }
    return false;
}

// `out vec4 fragColor;`, `layout(location = 0) out vec4 c;`
void Lint::declareOutputs(int i, int semi)
{
    if (is(i, "layout") && is(i + 1, "("))
        i = closeOf(i + 1) + 1;
    bool output = false;
    for (; isQualifier(text(i)) || is(i, "out"); ++i)
        output = output || is(i, "out");
    if (output && tok(i).word)
        declaration(i, semi, true);
}

const Function *Lint::function(std::string_view name) const
{
    for (const Function &f : functions)
        if (f.name == name)
            return &f;
    return nullptr;
}

} // namespace lint

std::vector<LintFinding> lintShader(const QByteArray &code)
{
    return lint::Lint(code).run();
}

} // namespace phonglab
