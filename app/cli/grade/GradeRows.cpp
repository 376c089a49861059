#include "GradeRows.h"

#include "core/check/MistakeSets.h"

namespace phonglab::cli {

const MistakeFinding *topFinding(const GradeRow &row)
{
    if (row.verdict != Verdict::Fail)
        return nullptr;
    const auto &findings = row.findings.report.diagnosis.findings;
    return findings.empty() ? nullptr : &findings.front();
}

QString rowMistakeKey(const GradeRow &row)
{
    if (const MistakeFinding *f = topFinding(row))
        return shaderMistakeKey(f->key);
    return row.verdict == Verdict::Fail ? QStringLiteral("unknown") : QString();
}

QString rowMistakeKeys(const GradeRow &row)
{
    if (row.verdict != Verdict::Fail)
        return {};
    const MistakeDiagnosis &d = row.findings.report.diagnosis;
    if (!d.together.variants.empty() && d.together.explains >= kExplainedConfidence)
        return mistakeSetKeys(d.together);
    return rowMistakeKey(row);
}

RowPlace rowPlace(const GradeRow &row)
{
    if (const MistakeFinding *f = topFinding(row)) {
        const std::vector<SourceLine> lines = mistakeSourceLines(f->key, row.findings.stages);
        if (!lines.empty())
            return {lines.front().file, lines.front().line};
        return {};
    }
    if (!row.findings.errors.empty())
        return {row.findings.errors.front().file, row.findings.errors.front().line};
    return {};
}

QString fileSlug(const QString &text)
{
    QString out;
    for (const QChar c : text.left(40))
        out += (c.isLetterOrNumber() && c.unicode() < 128) || c == QLatin1Char('-')
                || c == QLatin1Char('_')
            ? c
            : QLatin1Char('_');
    return out.isEmpty() ? QStringLiteral("_") : out;
}

void nameFilesWithin(GradeRow &row, const QString &folder)
{
    const QString prefix = folder + QLatin1Char('/');
    const auto own = [&](QString &path) {
        if (path.startsWith(prefix))
            path.remove(0, prefix.size());
    };
    for (ShaderDiagnostic &e : row.findings.errors)
        own(e.file);
    for (ShaderStageText &t : row.findings.stages)
        own(t.path);
    for (QStringList *texts : {&row.findings.warnings, &row.findings.notes})
        for (QString &text : *texts)
            text.replace(prefix, QString());
}

QString shownSubmissionName(const Submission &submission)
{
    const QString who = submission.student.isEmpty()
        ? submission.name
        : QStringLiteral("%1 (%2)").arg(submission.student, submission.participant);
    // A WebGL project's program: each is a row of its own.
    return submission.program.isEmpty() ? who
                                        : QStringLiteral("%1 · %2").arg(who, submission.program);
}

const SubmissionPage *GradeResults::pageOf(const GradeRow &row) const
{
    const std::size_t i = std::size_t(row.submission);
    return i < pages.size() && pages[i] ? &*pages[i] : nullptr;
}

} // namespace phonglab::cli
