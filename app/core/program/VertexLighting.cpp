#include "core/program/VertexLighting.h"

#include "core/program/GlslTokens.h"

#include <algorithm>

namespace phonglab {

namespace {

// Whether the text calls one of the equation's own functions.
bool callsLightingFunctions(const QByteArray &code)
{
    std::vector<std::string_view> macroWords;
    const std::vector<glsl::Token> tokens = glsl::tokenize(code, macroWords);
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i)
        if (tokens[i].word && glsl::oneOf(tokens[i].text, {"dot", "pow", "reflect"})
            && tokens[i + 1].text == "(")
            return true;
    // A macro may hide the call (`#define LAMBERT max(dot(N, L), 0.0)`).
    return std::any_of(macroWords.begin(), macroWords.end(), [](std::string_view w) {
        return glsl::oneOf(w, {"dot", "pow", "reflect"});
    });
}

// A `flat` output carries one colour per face (flat shading), which the
// image names per-face.
bool hasFlatOutput(const QByteArray &vertex)
{
    std::vector<std::string_view> macroWords;
    const std::vector<glsl::Token> tokens = glsl::tokenize(vertex, macroWords);
    return std::any_of(tokens.begin(), tokens.end(),
                       [](const glsl::Token &t) { return t.text == "flat"; });
}

} // namespace

bool lightsPerVertex(const QByteArray &vertex, const QByteArray &fragment)
{
    return callsLightingFunctions(vertex) && !callsLightingFunctions(fragment)
        && !hasFlatOutput(vertex);
}

} // namespace phonglab
