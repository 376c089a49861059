#pragma once
// Internal to BrowserRules*.cpp: the rewrite of one shader, declared here
// because it is defined in two files. BrowserRules.cpp walks the text (file
// scope, functions, statements) and makes the insertions; BrowserRulesZero.cpp
// spells the zero of each type and where it goes.
#include "core/program/BrowserRules.h"
#include "core/program/GlslTokens.h"
#include "core/program/ShaderDialect.h"

#include <QByteArray>

#include <optional>
#include <string_view>
#include <vector>

namespace phonglab::browserrules {

using namespace glsl;

// A variable's type and array size as its declaration gives them.
struct Declared {
    std::string_view type;
    int name = -1;      // its token; -1 for a built-in output, declared by no line
    int sizeBegin = -1; // the array size's tokens, [sizeBegin, sizeEnd); -1: no array
    int sizeEnd = -1;
    std::string_view builtIn = {}; // gl_Position, gl_FragColor
};

struct Member {
    std::string_view type;
    std::string_view arraySize; // a literal, or empty where the member is no array
    bool sizeIsLiteral = true;
};

struct StructType {
    std::string_view name;
    std::vector<Member> members;
};

// Bounds that keep arbitrary bytes from exhausting the time: a longer
// shader, or one deeper in structs, is handed on unchanged.
constexpr std::size_t kMaxTokens = 400000;
constexpr int kMaxStructDepth = 8;

class Rewriter
{
public:
    Rewriter(const QByteArray &code, ShaderStage stage)
        : m_code(code)
        , m_stage(stage)
        , m_es100(shaderDialectOf(code) == ShaderDialect::Es100)
        , m_tokens(tokenize(code, m_macroWords))
        , m_n(int(m_tokens.size()))
    {
    }

    BrowserRewrite run();

private:
    std::string_view text(int i) const { return i >= 0 && i < m_n ? m_tokens[i].text : ""; }
    bool is(int i, std::string_view t) const { return text(i) == t; }
    int closeOf(int i) const { return i >= 0 && i < m_n && m_partner[i] >= 0 ? m_partner[i] : m_n; }
    int skipBrackets(int i) const
    {
        return oneOf(text(i), {"(", "[", "{"}) ? closeOf(i) + 1 : i + 1;
    }

    void topLevel();
    bool isDeclarationBracket(int open) const;
    void clampIndices();
    void insertBefore(int token, const QByteArray &text);
    int globalDeclaration(int begin, int end);
    void function(int open, int body);
    void body(int open, int close);
    int localDeclaration(int begin, int close);
    int readStruct(int structWord);
    const StructType *structNamed(std::string_view name) const;
    std::string_view nameOf(const Declared &d) const
    {
        return d.name >= 0 ? text(d.name) : d.builtIn;
    }
    bool isType(std::string_view word) const { return isTypeName(word) || structNamed(word); }
    int declarators(int type, int end, std::vector<Declared> &unset) const;

    std::optional<QByteArray> zeroOf(std::string_view type, int depth = 0) const;
    std::optional<QByteArray> zeroing(const Declared &d) const;
    void insertAfter(int token, const QByteArray &text);
    void zeroAtDeclaration(const Declared &d, int semicolon);
    void noteZeroed(const Declared &d);
    void zeroAtEntry(int open, const std::vector<Declared> &variables);

    const QByteArray &m_code;
    ShaderStage m_stage;
    bool m_es100 = false;
    std::vector<std::string_view> m_macroWords;
    std::vector<Token> m_tokens;
    int m_n = 0;
    std::vector<int> m_partner;
    std::vector<StructType> m_structs;
    std::vector<Declared> m_globalsAtEntry; // outputs, and global arrays: zeroed as main() starts
    int m_mainBody = -1;
    BrowserRewrite m_out;
};

} // namespace phonglab::browserrules
