// The lint's walk of a function body: statements in the order they run,
// branches and loops joined into "set", "unset" or "maybe" for each
// variable, and each first read of an unset one recorded. Apart from
// ShaderLint.cpp, which reads the outline this walk starts from.
#include "core/program/ShaderLintWalk.h"

#include <QCoreApplication>

#include <algorithm>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ShaderLintWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ShaderLint)
};

namespace lint {

// Walks the statement at i; returns where the next one starts.
int Lint::statement(int i, int end)
{
    if (i >= end || gaveUp || nesting > kMaxNesting) {
        gaveUp = gaveUp || i < end;
        return end;
    }
    ++nesting;
    const int next = std::max(i + 1, walk(i, end));
    --nesting;
    return std::min(next, end);
}

int Lint::walk(int i, int end)
{
    const std::string_view w = text(i);
    const bool paren = is(i + 1, "(");
    if (w == "{")
        return block(i, end);
    if (w == "if" && paren)
        return ifStatement(i, end);
    if (w == "for" && paren)
        return forStatement(i, end);
    if (w == "do") { // once for sure, but a break may come before the write
        const int j = loop(i + 1, i + 1, i + 1, end);
        if (j < end && is(j, "while") && is(j + 1, "("))
            expression(j + 2, std::min(closeOf(j + 1), end));
        return until(j, end, ";") + 1;
    }
    if ((w == "while" || w == "switch") && paren) {
        const int close = std::min(closeOf(i + 1), end);
        expression(i + 2, close);
        if (w == "while")
            return loop(close, close, close + 1, end);
        const std::vector<Variable> before = vars; // a switch's cases may not run
        ++condition;
        const int next = statement(close + 1, end);
        --condition;
        join(before);
        return next;
    }
    if (w == "case" || (w == "default" && is(i + 1, ":")))
        return until(i, end, ":") + 1;
    const int semi = until(i, end, ";");
    const int type = declarationType(i);
    if (type >= 0)
        declaration(type, semi, false);
    else
        expression(i, semi);
    return semi + 1;
}

int Lint::block(int i, int end)
{
    const int close = std::min(closeOf(i), end);
    const std::size_t scope = vars.size();
    for (int j = i + 1; j < close;)
        j = statement(j, close);
    vars.resize(scope);
    return close + 1;
}

// Written in both branches is written; in one only, maybe.
int Lint::ifStatement(int i, int end)
{
    const int close = std::min(closeOf(i + 1), end);
    expression(i + 2, close);
    const std::vector<Variable> before = vars;
    ++condition;
    int j = statement(close + 1, end);
    const std::vector<Variable> taken = vars;
    vars = before;
    if (j < end && is(j, "else"))
        j = statement(j + 1, end);
    --condition;
    join(taken);
    return j;
}

int Lint::forStatement(int i, int end)
{
    const int close = std::min(closeOf(i + 1), end);
    const int first = until(i + 2, close, ";");
    const int second = until(first + 1, close, ";");
    const std::size_t scope = vars.size();
    const int type = declarationType(i + 2);
    if (type >= 0)
        declaration(type, first, false);
    else
        expression(i + 2, first);
    expression(first + 1, second);
    const int next = loop(second + 1, close, close + 1, end);
    vars.resize(scope);
    return next;
}

// A body that may run no times, or many. A variable the loop writes may
// be read before that write in a later round (`if (i > 0) sum += prev;
// prev = x;`): such a read under a condition in the body is not flagged.
int Lint::loop(int update, int updateEnd, int body, int end)
{
    std::vector<std::string_view> written;
    const int last = bodyEnd(body, end);
    for (int k = update; k < last; ++k) // the update, `)`, the body
        if (tok(k).word && !is(k - 1, ".") && use(k) == Use::Write)
            written.push_back(text(k));
    const std::vector<Variable> before = vars;
    ++condition;
    for (Variable &v : vars)
        if (v.state == State::Unset && v.loopDepth == 0
            && std::find(written.begin(), written.end(), v.name) != written.end())
            v.loopDepth = condition;
    const int next = statement(body, end);
    expression(update, updateEnd);
    for (std::size_t k = 0; k < before.size() && k < vars.size(); ++k)
        vars[k].loopDepth = before[k].loopDepth;
    --condition;
    join(before);
    return next;
}

// Where a loop body ends, or a little after (which only flags less): a
// block at its brace, another statement at its `;`, past any `else`.
int Lint::bodyEnd(int i, int end) const
{
    if (is(i, "{"))
        return std::min(closeOf(i), end);
    do
        i = until(i, end, ";") + 1;
    while (i < end && is(i, "else"));
    return std::min(i, end);
}

void Lint::join(const std::vector<Variable> &other)
{
    vars.resize(std::min(vars.size(), other.size()));
    for (std::size_t k = 0; k < vars.size(); ++k)
        if (vars[k].state != other[k].state)
            vars[k].state = State::Maybe;
}

// `vec3 c`, `const highp float x[2]`, `Light l`, `float[2] a`: a type
// word, a name, then what may follow a declared name. The type, or -1.
int Lint::declarationType(int i) const
{
    while (isQualifier(text(i)))
        ++i;
    const int k = is(i + 1, "[") ? closeOf(i + 1) + 1 : i + 1;
    const bool named = tok(i).word && tok(k).word && !isKeyword(text(i)) && !isKeyword(text(k));
    return named && oneOf(text(k + 1), {";", ",", "=", "["}) ? i : -1;
}

// `vec3 a = b, c;` sets a (after reading b) and leaves c unset.
void Lint::declaration(int type, int semi, bool output)
{
    int k = type + 1;
    while (is(k, "["))
        k = closeOf(k) + 1;
    while (k < semi && tok(k).word) {
        const int name = k++;
        while (is(k, "["))
            k = closeOf(k) + 1;
        const bool initialized = is(k, "=");
        if (initialized) {
            const int e = until(k + 1, semi, ",");
            if (!output)
                expression(k + 1, e);
            k = e;
        }
        if (output)
            outputs.push_back(name);
        else
            declare(name, initialized ? State::Set : State::Unset, false);
        if (!is(k++, ","))
            break;
    }
}

void Lint::declare(int name, State state, bool output)
{
    gaveUp = gaveUp || vars.size() >= kMaxVariables;
    // A macro may write it where this scan cannot see.
    const bool macro =
        std::find(macroWords.begin(), macroWords.end(), text(name)) != macroWords.end();
    vars.push_back({text(name), name, macro ? State::Maybe : state, output, 0});
}

void Lint::expression(int begin, int end)
{
    // A helper of the shader's own may set an output (`shade(); fragColor.a = 1.0;`).
    for (int i = begin; i < end; ++i)
        if (tok(i).word && is(i + 1, "(") && callMayWriteOutputs(text(i)))
            for (Variable &v : vars)
                if (v.output && v.state == State::Unset)
                    v.state = State::Maybe;
    // `x = x * 2.0` reads x before it writes it: writes count from the end.
    std::vector<int> writes;
    bool conditional = false; // past a `?`, `&&` or `||`: evaluated only sometimes
    for (int i = begin; i < end; ++i) {
        conditional = conditional || oneOf(text(i), {"?", "&&", "||"});
        const int v = tok(i).word && !is(i - 1, ".") && !is(i + 1, "(") ? lookup(text(i)) : -1;
        const Use u = v < 0 ? Use::None : use(i);
        if (u == Use::Write)
            writes.push_back(v);
        else if (u == Use::Read)
            read(vars[v], i, conditional);
    }
    for (int v : writes)
        vars[v].state = State::Set;
}

// `c = `, `c.x = ` and `a[i] = ` write; `c += `, `c++` and every other
// mention read.
Use Lint::use(int i) const
{
    int j = i + 1;
    while (is(j, "[") || (is(j, ".") && tok(j + 1).word)) {
        if (is(j, ".") && is(j + 1, "length") && is(j + 2, "("))
            return Use::None; // an array's length reads none of its values
        j = is(j, "[") ? closeOf(j) + 1 : j + 2;
    }
    if (is(i - 1, "++") || is(i - 1, "--"))
        return Use::Read;
    if (is(j, "="))
        return Use::Write;
    if ((is(i - 1, "(") || is(i - 1, ",")) && (is(j, ")") || is(j, ",")))
        return argumentUse(i);
    return Use::Read;
}

// A variable passed whole to a call: read by constructors, built-ins and
// `in` parameters; written by `out` and `inout` ones, and, to be safe, by
// a function the text does not declare (a macro, an extension).
Use Lint::argumentUse(int i) const
{
    const int open = enclosing[i];
    if (open < 0 || !is(open, "(") || !tok(open - 1).word)
        return Use::Read;
    const std::string_view callee = text(open - 1);
    if (function(callee)) {
        for (const Function &f : functions) // any overload
            if (f.name == callee && argument[i] < int(f.writes.size()) && f.writes[argument[i]])
                return Use::Write;
        return Use::Read;
    }
    const bool reads = isKeyword(callee) || isTypeName(callee) || onlyReads(callee)
        || std::find(structs.begin(), structs.end(), callee) != structs.end();
    return reads ? Use::Read : Use::Write;
}

void Lint::read(const Variable &v, int at, bool conditional)
{
    if (v.state != State::Unset
        || std::find(reported.begin(), reported.end(), v.declared) != reported.end())
        return;
    if (v.loopDepth > 0 && condition + int(conditional) > v.loopDepth)
        return;
    reported.push_back(v.declared);
    const QString name = QString::fromUtf8(v.name.data(), qsizetype(v.name.size()));
    const QString message = v.output
        ? ShaderLintWords::tr(
            "the output '%1' is read before it is written: its value is undefined in GLSL; "
            "a browser's WebGL starts it at 0 and PhongLab checks it so, but a GPU elsewhere "
            "may keep what was there")
        : ShaderLintWords::tr("'%1' is read before it is set: its value is undefined in GLSL; "
                              "a browser's WebGL starts it at 0 and PhongLab checks it so, but a "
                              "GPU elsewhere may keep what was there");
    using Kind = LintFinding::Kind;
    found.push_back({tok(at).line, tok(at).column, name,
                     v.output ? Kind::OutputReadBeforeWritten : Kind::ReadBeforeSet,
                     message.arg(name)});
}

bool Lint::callMayWriteOutputs(std::string_view name) const
{
    return std::any_of(functions.begin(), functions.end(),
                       [&](const Function &f) { return f.name == name && f.mayWriteOutputs; });
}

int Lint::lookup(std::string_view name) const
{
    for (int k = int(vars.size()) - 1; k >= 0; --k)
        if (vars[k].name == name)
            return k;
    return -1;
}

} // namespace lint

} // namespace phonglab
