#include "CheckReportOutput.h"
#include "core/check/MistakeSets.h"
#include "core/support/Language.h"

#include "ProgramFindings.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <cmath>
#include <limits>

namespace phonglab {

namespace {

// The text output's sentences, in the language the run speaks
// (core/support/Language); the JSON's keys and key values never change with it.
struct CheckWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::CheckReportOutput)
};

// The verdict as the text output says it.
QString verdictWord(Verdict v)
{
    switch (v) {
    case Verdict::Pass: return CheckWords::tr("pass");
    case Verdict::Fail: return CheckWords::tr("fail");
    case Verdict::Error: break;
    case Verdict::Timeout: return CheckWords::tr("timeout");
    case Verdict::Crash: return CheckWords::tr("crash");
    }
    return CheckWords::tr("error");
}

// The finding's own lines, then those of the mistakes it names beside it.
std::vector<SourceLine> findingLines(const MistakeFinding &f,
                                     const std::vector<ShaderStageText> &stages)
{
    std::vector<SourceLine> lines = mistakeSourceLines(f.key, stages);
    for (ShaderMistake m : f.also)
        for (const SourceLine &l : mistakeSourceLines(m, stages))
            if (std::none_of(lines.begin(), lines.end(), [&](const SourceLine &o) {
                    return o.file == l.file && o.line == l.line;
                }))
                lines.push_back(l);
    return lines;
}

QString findingMessage(const MistakeFinding &f)
{
    QString text = f.fromCode
        ? CheckWords::tr("%1: the vertex shader computes the lighting and the fragment shader "
                         "interpolates it (its image alone explains %2 % of the difference): %3")
              .arg(shaderMistakeKey(f.key))
              .arg(qRound(100.0 * f.confidence))
              .arg(shaderMistakeRule(f.key))
        : CheckWords::tr("%1 explains %2 % of the difference (%3): %4")
              .arg(shaderMistakeKey(f.key))
              .arg(qRound(100.0 * f.confidence))
              .arg(mistakeFormSummary({f.key, f.form}), shaderMistakeRule(f.key));
    for (ShaderMistake m : f.also)
        text += CheckWords::tr("; or, with the same image, %1: %2")
                    .arg(shaderMistakeKey(m), shaderMistakeRule(m));
    return text;
}

QString objectLabel(const Scene &scene, int object)
{
    if (object < 0 || std::size_t(object) >= scene.objects.size())
        return CheckWords::tr("the background");
    return CheckWords::tr("object %1 (%2)")
        .arg(object)
        .arg(scene.objects[std::size_t(object)].mesh);
}

QJsonArray keysJson(const std::vector<ShaderMistake> &mistakes)
{
    QJsonArray out;
    for (ShaderMistake m : mistakes)
        out.append(shaderMistakeKey(m));
    return out;
}

QJsonObject unknownFinding()
{
    return {{QStringLiteral("key"), QStringLiteral("unknown")},
            {QStringLiteral("also"), QJsonArray()},
            {QStringLiteral("confidence"), 0.0},
            {QStringLiteral("message"),
             CheckWords::tr("no classic mistake explains the difference; "
                            "the error heatmap (--diff) shows where it is")},
            {QStringLiteral("lines"), QJsonArray()}};
}

QJsonArray diagnosisJson(const CheckFindings &outcome)
{
    QJsonArray out;
    const MistakeDiagnosis &d = outcome.report.diagnosis;
    if (d.unexplained())
        out.append(unknownFinding());
    for (const MistakeFinding &f : d.findings) {
        QJsonArray lines;
        for (const SourceLine &l : findingLines(f, outcome.stages))
            lines.append(QJsonObject{{QStringLiteral("file"), l.file},
                                     {QStringLiteral("line"), l.line},
                                     {QStringLiteral("text"), l.text}});
        out.append(QJsonObject{{QStringLiteral("key"), shaderMistakeKey(f.key)},
                               {QStringLiteral("form"), mistakeFormSummary({f.key, f.form})},
                               {QStringLiteral("also"), keysJson(f.also)},
                               {QStringLiteral("confidence"), f.confidence},
                               {QStringLiteral("from_code"), f.fromCode},
                               {QStringLiteral("message"), findingMessage(f)},
                               {QStringLiteral("lines"), lines}});
    }
    return out;
}

// The smallest set of mistakes that explains the render, each with its
// likely lines: `together` {keys, explains, forms, lines, beyond_limit},
// where it explains enough (MistakeDiagnosis::togetherExplains); below that
// the closest set is `partial`, of the same shape, and `together` is null.
QJsonValue setJson(Verdict verdict, const CheckFindings &outcome, bool explaining)
{
    const MistakeDiagnosis &d = outcome.report.diagnosis;
    const MistakeSet &set = d.together;
    if (verdict != Verdict::Fail || set.variants.empty() || d.togetherExplains() != explaining)
        return QJsonValue();
    QJsonArray keys, forms, lines;
    for (MistakeVariant v : set.variants) {
        keys.append(shaderMistakeKey(v.key));
        forms.append(mistakeFormSummary(v));
        for (const SourceLine &l : mistakeSourceLines(v.key, outcome.stages))
            lines.append(QJsonObject{{QStringLiteral("key"), shaderMistakeKey(v.key)},
                                     {QStringLiteral("file"), l.file},
                                     {QStringLiteral("line"), l.line},
                                     {QStringLiteral("text"), l.text}});
    }
    return QJsonObject{{QStringLiteral("keys"), keys},
                       {QStringLiteral("explains"), set.explains},
                       {QStringLiteral("forms"), forms},
                       {QStringLiteral("lines"), lines},
                       {QStringLiteral("beyond_limit"), set.beyondLimit}};
}

QJsonArray errorsJson(const std::vector<ShaderDiagnostic> &errors)
{
    QJsonArray out;
    for (const ShaderDiagnostic &e : errors)
        out.append(QJsonObject{{QStringLiteral("file"), e.file},
                               {QStringLiteral("line"), e.line},
                               {QStringLiteral("column"), e.column},
                               {QStringLiteral("message"), e.message}});
    return out;
}

} // namespace

QJsonObject precisionJson(const PrecisionFinding &p)
{
    QJsonObject o{{QStringLiteral("judged"), precisionRuleKey(p.checkedAt)},
                  {QStringLiteral("declared"), QJsonArray::fromStringList(p.declared)}};
    o.insert(QStringLiteral("as_written_max_error"),
             p.asWrittenMaxError ? QJsonValue(*p.asWrittenMaxError) : QJsonValue());
    o.insert(QStringLiteral("as_written_error"),
             p.asWrittenError.isEmpty() ? QJsonValue() : QJsonValue(p.asWrittenError));
    o.insert(QStringLiteral("as_written_psnr_db"),
             p.asWrittenMaxError && std::isfinite(p.asWrittenPsnr) ? QJsonValue(p.asWrittenPsnr)
                                                                   : QJsonValue());
    return o;
}

PrecisionFinding precisionFromJson(const QJsonObject &o)
{
    PrecisionFinding p;
    p.checkedAt = precisionRuleFromKey(o.value(QStringLiteral("judged")).toString())
                      .value_or(PrecisionRule::Highp);
    for (const QJsonValue &v : o.value(QStringLiteral("declared")).toArray())
        p.declared << v.toString();
    if (const QJsonValue e = o.value(QStringLiteral("as_written_max_error")); e.isDouble())
        p.asWrittenMaxError = e.toInt();
    p.asWrittenError = o.value(QStringLiteral("as_written_error")).toString();
    const QJsonValue psnr = o.value(QStringLiteral("as_written_psnr_db"));
    p.asWrittenPsnr = psnr.isDouble() ? psnr.toDouble() : std::numeric_limits<double>::infinity();
    return p;
}

QString precisionText(const PrecisionFinding &p)
{
    if (p.declared.isEmpty())
        return {};
    const QString declared = p.declared.join(QStringLiteral(", "));
    if (p.checkedAt == PrecisionRule::AsWritten)
        return CheckWords::tr("precision: %1 checked as written, as this driver computes it")
            .arg(declared);
    if (!p.asWrittenError.isEmpty())
        return CheckWords::tr("precision: %1 checked at highp (32-bit floats), as a desktop "
                              "browser computes it; as written the program does not build on a "
                              "driver that honours precision (a browser too): %2")
            .arg(declared, p.asWrittenError);
    if (!p.asWrittenMaxError)
        return CheckWords::tr("precision: %1 checked at highp (32-bit floats), as a desktop "
                              "browser computes it")
            .arg(declared);
    if (*p.asWrittenMaxError == 0)
        return CheckWords::tr("precision: %1 checked at highp (32-bit floats), as a desktop "
                              "browser computes it; as written it draws the same image here")
            .arg(declared);
    return CheckWords::tr("precision: %1 checked at highp (32-bit floats), as a desktop browser "
                          "computes it; as written, on a driver that computes %1 in fewer bits "
                          "(this one does), the image changes by up to %2/255 (PSNR %3 dB): "
                          "not counted against the shader")
        .arg(declared)
        .arg(*p.asWrittenMaxError)
        .arg(std::isfinite(p.asWrittenPsnr) ? sentenceNumber(p.asWrittenPsnr, 'f', 1)
                                            : QStringLiteral("∞"));
}

QJsonObject checkJson(Verdict verdict, const CheckFindings &findings)
{
    const bool checked = verdict != Verdict::Error;
    const ImageComparison &c = findings.report.comparison;
    QJsonObject o;
    o.insert(QStringLiteral("verdict"), verdictName(verdict));
    // Identical images have an infinite PSNR, which JSON cannot write: null.
    o.insert(QStringLiteral("psnr_db"),
             checked && std::isfinite(c.psnr) ? QJsonValue(c.psnr) : QJsonValue());
    o.insert(QStringLiteral("max_error"), checked ? QJsonValue(c.maxError) : QJsonValue());
    o.insert(QStringLiteral("bad_fraction"),
             checked ? QJsonValue(findings.report.badFraction()) : QJsonValue());
    o.insert(QStringLiteral("tolerance"), findings.report.toleranceSteps);
    QJsonObject worst;
    // No worst pixel when every compared pixel is exact.
    const bool hasWorst = checked && c.pixelsCompared > 0 && c.maxError > 0;
    if (hasWorst) {
        worst.insert(QStringLiteral("x"), c.worstPixel.x());
        worst.insert(QStringLiteral("y"), c.worstPixel.y());
        worst.insert(QStringLiteral("object"),
                     findings.report.worstObject >= 0 ? QJsonValue(findings.report.worstObject)
                                                      : QJsonValue());
    }
    o.insert(QStringLiteral("worst"), hasWorst ? QJsonValue(worst) : QJsonValue());
    o.insert(QStringLiteral("diagnosis"), diagnosisJson(findings));
    o.insert(QStringLiteral("together"), setJson(verdict, findings, true));
    o.insert(QStringLiteral("partial"), setJson(verdict, findings, false));
    o.insert(QStringLiteral("undetectable"), keysJson(findings.report.diagnosis.undetectable));
    QJsonArray silent;
    for (const SilentTerm &t : findings.report.silent)
        silent.append(QJsonObject{{QStringLiteral("term"), silentTermKey(t.term)},
                                  {QStringLiteral("why"), t.why}});
    o.insert(QStringLiteral("unchecked_terms"), silent);
    o.insert(QStringLiteral("errors"), errorsJson(findings.errors));
    QJsonObject bindings;
    for (const VariableBinding &b : findings.bindings.variables)
        if (b.meaning || b.isExplicit)
            bindings.insert(b.variable.name,
                            b.meaning ? bindingMeaningKey(*b.meaning) : kUnboundWord);
    o.insert(QStringLiteral("bindings"), bindings);
    // Why each variable no name decided means what it does (extends
    // "bindings", whose values stay the meanings' keys).
    QJsonObject byUse;
    for (const VariableBinding &b : findings.bindings.variables)
        if (b.meaning && b.byUse)
            byUse.insert(b.variable.name,
                         QJsonObject{{QStringLiteral("meaning"), bindingMeaningKey(*b.meaning)},
                                     {QStringLiteral("reason"), b.byUse->reason},
                                     {QStringLiteral("stage"), stageName(b.byUse->stage)},
                                     {QStringLiteral("line"), b.byUse->line}});
    o.insert(QStringLiteral("bindings_by_use"), byUse);
    o.insert(QStringLiteral("equation"),
             checked ? QJsonValue(phongEquationKey(findings.report.equation)) : QJsonValue());
    o.insert(QStringLiteral("notes"), QJsonArray::fromStringList(findings.notes));
    o.insert(QStringLiteral("warnings"), QJsonArray::fromStringList(findings.warnings));
    o.insert(QStringLiteral("precision"), precisionJson(findings.precision));
    return o;
}

namespace {

// What the verdict rests on: how the names were bound, the notes, precision.
QStringList groundsLines(const CheckOutcome &outcome)
{
    QStringList out;
    if (const QString bound = bindingsText(outcome.bindings); !bound.isEmpty())
        out << CheckWords::tr("bindings: %1").arg(bound);
    for (const QString &line : bindingsByUseText(outcome.bindings))
        out << CheckWords::tr("bound by use: %1").arg(line);
    for (const QString &note : outcome.notes)
        out << CheckWords::tr("note: %1").arg(note);
    if (const QString precision = precisionText(outcome.precision); !precision.isEmpty())
        out << precision;
    return out;
}

QStringList comparisonLines(const CheckOutcome &outcome, const Scene &scene)
{
    QStringList out;
    const CheckReport &r = outcome.report;
    const ImageComparison &c = r.comparison;
    out << CheckWords::tr("check: %1").arg(verdictWord(outcome.verdict));
    out << CheckWords::tr(
               "%1, max error %2/255 (tolerance %3/255), %4 % of %5 compared pixels over it")
               .arg(std::isfinite(c.psnr)
                        ? CheckWords::tr("PSNR %1 dB").arg(sentenceNumber(c.psnr, 'f', 2))
                        : CheckWords::tr("PSNR inf"))
               .arg(c.maxError)
               .arg(r.toleranceSteps)
               .arg(sentenceNumber(100.0 * r.badFraction(), 'f', 2))
               .arg(c.pixelsCompared);
    if (outcome.verdict == Verdict::Pass && r.equation == PhongEquation::Slide)
        out << CheckWords::tr("equation: the slide's, taken literally (a highlight even where "
                              "N·L <= 0), which is right too");
    if (c.pixelsCompared > 0 && c.maxError > 0)
        out << CheckWords::tr("worst pixel (%1, %2) on %3")
                   .arg(c.worstPixel.x())
                   .arg(c.worstPixel.y())
                   .arg(objectLabel(scene, r.worstObject));
    return out;
}

// The set of mistakes that explains the render together, each with its lines.
QStringList togetherLines(const MistakeDiagnosis &d, const std::vector<ShaderStageText> &stages)
{
    QStringList out;
    out << CheckWords::tr("  together: %1 explain %2 % of the difference")
               .arg(mistakeSetName(d.together))
               .arg(qRound(100.0 * d.together.explains));
    for (MistakeVariant v : d.together.variants) {
        out << QStringLiteral("    %1 (%2): %3")
                   .arg(shaderMistakeKey(v.key), mistakeFormSummary(v), shaderMistakeRule(v.key));
        for (const SourceLine &l : mistakeSourceLines(v.key, stages))
            out << QStringLiteral("      %1:%2: %3").arg(l.file).arg(l.line).arg(l.text);
    }
    if (!d.findings.empty())
        out << CheckWords::tr("  each alone:");
    return out;
}

// A failed check's diagnosis: what explains the difference, or that nothing does.
QStringList diagnosisLines(const MistakeDiagnosis &d, const std::vector<ShaderStageText> &stages)
{
    QStringList out;
    out << CheckWords::tr("diagnosis:");
    if (d.unexplained()) {
        out << CheckWords::tr(
            "  unknown: no classic mistake explains the difference; the heatmap (--diff) "
            "shows where it is");
        if (!d.together.variants.empty())
            out << CheckWords::tr("  closest, partial: %1 explain %2 % of the difference")
                       .arg(mistakeSetName(d.together))
                       .arg(qRound(100.0 * d.together.explains));
    }
    if (d.together.beyondLimit)
        out << CheckWords::tr("  more than %1 deviations would be needed to explain all of "
                              "it: the heatmap shows the rest")
                   .arg(kMaxMistakesTogether);
    if (d.together.variants.size() > 1 && d.togetherExplains())
        out << togetherLines(d, stages);
    for (const MistakeFinding &f : d.findings) {
        out << QStringLiteral("  ") + findingMessage(f);
        for (const SourceLine &l : findingLines(f, stages))
            out << QStringLiteral("    %1:%2: %3").arg(l.file).arg(l.line).arg(l.text);
    }
    return out;
}

// What this scene cannot judge: mistakes it cannot show, terms it does not check.
QStringList unseenLines(const CheckReport &r)
{
    QStringList out;
    const MistakeDiagnosis &d = r.diagnosis;
    if (!d.undetectable.empty()) {
        QStringList keys;
        for (ShaderMistake m : d.undetectable)
            keys << shaderMistakeKey(m);
        out << CheckWords::tr("cannot show in this scene: %1").arg(keys.join(QStringLiteral(", ")));
    }
    if (!r.silent.empty())
        out << CheckWords::tr("not checked in this scene: %1").arg(silentTermsText(r.silent));
    return out;
}

} // namespace

QString checkText(const CheckOutcome &outcome, const Scene &scene)
{
    QStringList out = groundsLines(outcome);
    if (outcome.verdict == Verdict::Error) {
        out << CheckWords::tr("check: error");
        return out.join(QLatin1Char('\n'));
    }
    out << comparisonLines(outcome, scene);
    if (outcome.verdict == Verdict::Fail)
        out << diagnosisLines(outcome.report.diagnosis, outcome.stages);
    out << unseenLines(outcome.report);
    return out.join(QLatin1Char('\n'));
}

} // namespace phonglab
