#pragma once
// Internal to ShaderLint*.cpp: the lint of one shader, declared here because
// it is defined in two files. ShaderLint.cpp reads the shader's outline (its
// brackets, functions and `out` variables); ShaderLintWalk.cpp walks each
// function's statements in the order they run, following which variables are
// set, and records the reads it finds.
#include "core/program/GlslTokens.h"
#include "core/program/ShaderLint.h"

#include <QByteArray>

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <vector>

namespace phonglab::lint {

// Bounds that keep arbitrary bytes from exhausting the stack or the time: a
// shader past them is not checked at all.
constexpr int kMaxNesting = 200; // statements in statements
constexpr std::size_t kMaxVariables = 2000;

using namespace glsl;

enum class State {
    Unset,
    Maybe, // written on some paths only: never flagged
    Set,
};

enum class Use {
    Read,
    Write,
    None,
};

struct Variable {
    std::string_view name;
    int declared = 0; // its name's token: which declaration this is
    State state = State::Unset;
    bool output = false;
    int loopDepth = 0; // the body depth of a loop that writes it later; 0 outside
};

struct Function {
    std::string_view name;
    int body = -1;               // its '{', -1 for a prototype
    std::vector<bool> writes;    // per parameter: out or inout
    std::vector<int> parameters; // their names' tokens
    bool mayWriteOutputs = false;
};

class Lint
{
public:
    explicit Lint(const QByteArray &code);
    std::vector<LintFinding> run();

private:
    const Token &tok(int i) const { return i >= 0 && i < n ? tokens[i] : none; }
    std::string_view text(int i) const { return tok(i).text; }
    bool is(int i, std::string_view t) const { return text(i) == t; }
    bool opens(int i) const { return oneOf(text(i), {"(", "[", "{"}); }
    int closeOf(int i) const { return i >= 0 && i < n && partner[i] >= 0 ? partner[i] : n; }

    // The first `stop`, `;` or unmatched `}` at this bracket level from i, or end.
    int until(int i, int end, std::string_view stop) const
    {
        while (i < end && !is(i, stop) && !is(i, ";") && !is(i, "}"))
            i = opens(i) ? closeOf(i) + 1 : i + 1;
        return std::min(i, end);
    }

    // The outline (ShaderLint.cpp).
    void matchBrackets();
    void readTopLevel();
    void addFunction(int open, int body);
    bool mayWriteOutputs(const Function &f) const;
    void declareOutputs(int i, int semi);
    const Function *function(std::string_view name) const;

    // The walk of a function body (ShaderLintWalk.cpp).
    int statement(int i, int end);
    int walk(int i, int end);
    int block(int i, int end);
    int ifStatement(int i, int end);
    int forStatement(int i, int end);
    int loop(int update, int updateEnd, int body, int end);
    int bodyEnd(int i, int end) const;
    void join(const std::vector<Variable> &other);
    int declarationType(int i) const;
    void declaration(int type, int semi, bool output);
    void declare(int name, State state, bool output);
    void expression(int begin, int end);
    Use use(int i) const;
    Use argumentUse(int i) const;
    void read(const Variable &v, int at, bool conditional);
    bool callMayWriteOutputs(std::string_view name) const;
    int lookup(std::string_view name) const;

    std::vector<std::string_view> macroWords; // every word of a preprocessor line
    std::vector<Token> tokens;
    int n = 0;
    Token none;
    std::vector<int> partner;   // of each bracket; n for an unclosed one, -1 for others
    std::vector<int> enclosing; // the innermost open bracket around each token, -1 for none
    std::vector<int> argument;  // the commas before each token inside that bracket
    std::vector<Function> functions;
    std::vector<std::string_view> structs;
    std::vector<int> outputs; // names of the global `out` variables
    // The walk of one function body.
    std::vector<Variable> vars; // in scope, innermost last
    std::vector<int> reported;  // declarations already flagged
    std::vector<LintFinding> found;
    int condition = 0; // branches and loop bodies around the walk
    int nesting = 0;
    bool gaveUp = false;
};

} // namespace phonglab::lint
