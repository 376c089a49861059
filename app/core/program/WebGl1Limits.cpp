#include "core/program/WebGl1Limits.h"

#include "core/program/GlslTokens.h"
#include "core/program/ShaderDialect.h"

#include <QCoreApplication>

#include <algorithm>

namespace phonglab {

namespace {

struct WebGl1Words {
    Q_DECLARE_TR_FUNCTIONS(phonglab::WebGl1Limits)
};

using namespace glsl;

QString spelled(std::string_view s)
{
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

// The names declared `uniform`, `attribute` or `varying`: values no
// constant expression may hold.
std::vector<std::string_view> nonConstants(const std::vector<Token> &tokens)
{
    std::vector<std::string_view> out;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        if (!oneOf(tokens[i].text, {"uniform", "attribute", "varying"}))
            continue;
        for (std::size_t k = i + 1; k < tokens.size() && tokens[k].text != ";"; ++k)
            if (tokens[k].word && k + 1 < tokens.size()
                && oneOf(tokens[k + 1].text, {";", ",", "["}))
                out.push_back(tokens[k].text);
    }
    return out;
}

} // namespace

std::vector<WebGlRefusal> webGl1Refusals(const QByteArray &code)
{
    if (shaderDialectOf(code) != ShaderDialect::Es100)
        return {};
    std::vector<std::string_view> macroWords;
    const std::vector<Token> tokens = tokenize(code, macroWords);
    const std::vector<std::string_view> variable = nonConstants(tokens);
    const auto isVariable = [&](std::string_view w) {
        return std::find(variable.begin(), variable.end(), w) != variable.end();
    };
    std::vector<WebGlRefusal> out;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const Token &t = tokens[i];
        if (t.word && oneOf(t.text, {"while", "do"})
            && (i == 0 || tokens[i - 1].text != "}" || t.text == "do")) {
            // `} while (...)` ends a do loop already refused at its `do`.
            out.push_back({t.line, t.column,
                           WebGl1Words::tr("WebGL 1 has no %1 loops (GLSL ES 1.00, appendix A): "
                                           "the browser refuses this shader (\"This type of "
                                           "loop is not allowed\"); write a for loop with a "
                                           "constant bound")
                               .arg(spelled(t.text))});
            continue;
        }
        if (!(t.text == "for" && i + 1 < tokens.size() && tokens[i + 1].text == "("))
            continue;
        // The init up to the first `;`, the condition up to the second.
        int part = 0;
        for (std::size_t k = i + 2; k < tokens.size() && part < 2; ++k) {
            if (tokens[k].text == ";") {
                ++part;
                continue;
            }
            if (!tokens[k].word || !isVariable(tokens[k].text))
                continue;
            out.push_back(
                {tokens[k].line, tokens[k].column,
                 (part == 0 ? WebGl1Words::tr("'%1' is no constant: WebGL 1 starts a loop's index "
                                              "at a constant, and the browser refuses this shader "
                                              "(\"Loop index cannot be initialized with "
                                              "non-constant expression\")")
                            : WebGl1Words::tr("'%1' is no constant: WebGL 1 compares a loop's "
                                              "index with a constant, and the browser refuses "
                                              "this shader (\"Loop index cannot be compared with "
                                              "non-constant expression\"); bound the loop by a "
                                              "constant and break at the count"))
                     .arg(spelled(tokens[k].text))});
            break;
        }
    }
    return out;
}

} // namespace phonglab
