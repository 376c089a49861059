#pragma once
#include <QByteArray>

#include <cstddef>
#include <initializer_list>
#include <string_view>
#include <vector>

// GLSL text as tokens, for what reads a shader without compiling it
// (ShaderLint): words, numbers and operators with their line and column,
// comments and preprocessor lines left out (the words a directive names are
// handed back apart: a macro may stand for any of them).
namespace phonglab::glsl {

using Words = std::initializer_list<std::string_view>;
bool oneOf(std::string_view word, Words words);

bool isDigit(char c);
bool isWordStart(char c);
bool isWordChar(char c);
// Whether `word` is one of the words of `list`, which has a space around each.
bool listed(std::string_view list, std::string_view word);
bool isKeyword(std::string_view w);   // if, for, return, struct, precision, ...
bool isQualifier(std::string_view w); // const, highp, flat, ...
// float, ivec3, mat4, dmat2x3: a constructor when called.
bool isTypeName(std::string_view w);
// Built-ins that only read their arguments (modf and frexp write one: absent).
bool onlyReads(std::string_view f);

struct Token {
    bool word = false;
    std::string_view text; // into the code given to tokenize()
    int line = 0;          // 1-based
    int column = 0;        // 1-based, in characters (UTF-8)
};

// Where the token starting at `i` ends: a number, a word, an operator of up
// to three characters, or one character.
std::size_t tokenEnd(std::string_view s, std::size_t i);
// `code` as tokens; `macroWords` receives every word of every directive.
std::vector<Token> tokenize(const QByteArray &code, std::vector<std::string_view> &macroWords);
// Each bracket's partner, by token index: -1 for tokens that are no
// bracket and for a bracket that closes none or is never closed.
std::vector<int> bracketPartners(const std::vector<Token> &tokens);

} // namespace phonglab::glsl
