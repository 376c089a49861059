#include "CheckMarks.h"

#include "core/check/MistakeSets.h"

namespace phonglab {

namespace {

ShaderDiagnostic mark(int line, const QString &message)
{
    ShaderDiagnostic d;
    d.severity = ShaderDiagnostic::Severity::Warning;
    d.line = line;
    d.message = message;
    return d;
}

// The mistakes the verdict names: the set that explains it together, else
// each finding with the ones it cannot be told from.
std::vector<ShaderMistake> namedMistakes(const MistakeDiagnosis &d)
{
    std::vector<ShaderMistake> out;
    const auto add = [&](ShaderMistake m) {
        if (std::find(out.begin(), out.end(), m) == out.end())
            out.push_back(m);
    };
    if (d.together.variants.size() > 1 && d.togetherExplains())
        for (MistakeVariant v : d.together.variants)
            add(v.key);
    for (const MistakeFinding &f : d.findings) {
        add(f.key);
        for (ShaderMistake m : f.also)
            add(m);
    }
    return out;
}

} // namespace

CheckMarks checkMarks(const CheckedFrame &result)
{
    CheckMarks marks;
    const CheckOutcome &outcome = result.outcome;
    for (const ShaderStageText &stage : outcome.stages) {
        std::vector<ShaderDiagnostic> &into = stage.vertex ? marks.vertex : marks.fragment;
        for (const UnboundUniform &u : result.unbound)
            if (const int line = uniformDeclarationLine(stage.text, u.name); line > 0)
                into.push_back(mark(
                    line,
                    QObject::tr("%1: choose what it means in Uniforms").arg(unboundSentence(u))));
        if (outcome.verdict != Verdict::Fail)
            continue;
        for (ShaderMistake m : namedMistakes(outcome.report.diagnosis))
            for (const SourceLine &l : mistakeSourceLines(m, {stage}))
                into.push_back(mark(
                    l.line,
                    QObject::tr("check: %1 — %2").arg(shaderMistakeKey(m), shaderMistakeRule(m))));
    }
    return marks;
}

} // namespace phonglab
