#include "core/check/MistakeSourceLines.h"

#include <QRegularExpression>

namespace phonglab {

namespace {

constexpr int kMaxLinesPerStage = 3;

enum class Stage {
    Vertex,
    Fragment,
    Both
};

struct Pattern {
    Stage stage;
    const char *regex;
};

// The line patterns of each mistake's term, most telling first: the first
// pattern that matches any line of a stage is the one used for that stage.
std::vector<Pattern> patternsFor(ShaderMistake mistake)
{
    switch (mistake) {
    case ShaderMistake::NormalMatrix:
        return {{Stage::Vertex, R"(=.*\*.*\bnormal\b)"}, {Stage::Both, R"(\bnormalMatrix\b)"}};
    case ShaderMistake::Unnormalized:
        return {{Stage::Fragment, R"(\bN\s*=)"},
                {Stage::Fragment, R"(\bL\s*=[^=])"},
                {Stage::Fragment, R"(normalize\s*\()"}};
    case ShaderMistake::LightSpace: return {{Stage::Both, R"(\blightPosition\b)"}};
    case ShaderMistake::HomogeneousW: return {{Stage::Both, R"(\*\s*vec4\s*\()"}};
    case ShaderMistake::ReflectIncident: return {{Stage::Both, R"(\breflect\s*\()"}};
    case ShaderMistake::ViewVector: return {{Stage::Both, R"(\bV\s*=[^=])"}};
    case ShaderMistake::Attenuation:
        return {{Stage::Both, R"(\bf_?att\w*\s*=[^=])"}, {Stage::Both, R"(\battenuation\s*\[)"}};
    case ShaderMistake::NegativeLight:
        return {{Stage::Both, R"(dot\s*\(\s*N\s*,\s*L\s*\)|dot\s*\(\s*L\s*,\s*N\s*\))"}};
    case ShaderMistake::BackfaceSpecular:
        return {{Stage::Both, R"(\bif\s*\(.*(NdotL|dot\s*\(\s*N\s*,\s*L))"},
                {Stage::Both, R"(\bpow\s*\()"}};
    case ShaderMistake::Ambient: return {{Stage::Both, R"(\bIa\b.*\bka\b|\bka\b.*\bIa\b)"}};
    case ShaderMistake::Gouraud: return {{Stage::Vertex, R"(\bdot\s*\(|\bpow\s*\()"}};
    case ShaderMistake::PerFace:
        // A face normal comes from a flat varying or from the derivatives.
        return {{Stage::Both, R"(\bflat\s+(out|in)\b|\bdFd[xy]\s*\(|\bcross\s*\()"}};
    case ShaderMistake::HalfwayVector:
        return {{Stage::Both, R"(normalize\s*\(\s*\w+\s*\+\s*\w+\s*\))"},
                {Stage::Both, R"(\b[hH]\w*\s*=[^=])"},
                {Stage::Both, R"(\bpow\s*\()"}};
    }
    return {};
}

// Declarations and comments name the term without computing it.
bool computes(const QString &trimmed)
{
    static const QRegularExpression declaration(
        QStringLiteral(R"(^(uniform|in|out|layout|const|#|//|\*))"));
    return !trimmed.isEmpty() && !declaration.match(trimmed).hasMatch();
}

std::vector<SourceLine> matchingLines(const ShaderStageText &stage, const QRegularExpression &regex)
{
    std::vector<SourceLine> out;
    const QStringList lines = stage.text.split(QLatin1Char('\n'));
    for (int i = 0; i < lines.size() && int(out.size()) < kMaxLinesPerStage; ++i) {
        const QString trimmed = lines[i].trimmed();
        if (computes(trimmed) && regex.match(trimmed).hasMatch())
            out.push_back({stage.path, i + 1, trimmed});
    }
    return out;
}

} // namespace

std::vector<SourceLine> mistakeSourceLines(ShaderMistake mistake,
                                           const std::vector<ShaderStageText> &stages)
{
    std::vector<SourceLine> out;
    for (const ShaderStageText &stage : stages) {
        for (const Pattern &pattern : patternsFor(mistake)) {
            if (pattern.stage != Stage::Both && (pattern.stage == Stage::Vertex) != stage.vertex)
                continue;
            const std::vector<SourceLine> found =
                matchingLines(stage, QRegularExpression(QString::fromLatin1(pattern.regex)));
            if (!found.empty()) {
                out.insert(out.end(), found.begin(), found.end());
                break;
            }
        }
    }
    return out;
}

} // namespace phonglab
