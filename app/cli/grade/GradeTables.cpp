#include "GradeTables.h"

#include <QHash>

#include "bench/BenchResult.h"
#include "render/check/ProgramFindings.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <cmath>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct GradeTablesWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::GradeTables)
};

namespace {

const QStringList &csvColumns()
{
    static const QStringList columns{QStringLiteral("submission"),
                                     QStringLiteral("scene"),
                                     QStringLiteral("verdict"),
                                     QStringLiteral("psnr_db"),
                                     QStringLiteral("max_error"),
                                     QStringLiteral("bad_fraction"),
                                     QStringLiteral("key"),
                                     QStringLiteral("also"),
                                     QStringLiteral("file"),
                                     QStringLiteral("line"),
                                     QStringLiteral("equation"),
                                     QStringLiteral("bindings"),
                                     QStringLiteral("seconds"),
                                     QStringLiteral("mistakes"),
                                     QStringLiteral("program"),
                                     QStringLiteral("student"),
                                     QStringLiteral("participant"),
                                     QStringLiteral("page_fidelity"),
                                     QStringLiteral("page_own_scene"),
                                     QStringLiteral("page_javascript"),
                                     QStringLiteral("page_error")};
    return columns;
}

// Quoted for CSV, and never a formula: a spreadsheet runs a cell that starts
// with = + - @ (or a tab or carriage return before one).
QString textCell(const QString &text)
{
    static const QString formulaStarts = QStringLiteral("=+-@\t\r");
    if (!text.isEmpty() && formulaStarts.contains(text.front()))
        return csvField(QLatin1Char('\'') + text);
    return csvField(text);
}

bool checked(const GradeRow &row)
{
    return row.verdict == Verdict::Pass || row.verdict == Verdict::Fail;
}

// The check's verdict the row's stands for: a timeout or a crash checked nothing.
Verdict checkVerdict(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Pass: return Verdict::Pass;
    case Verdict::Fail: return Verdict::Fail;
    case Verdict::Error:
    case Verdict::Timeout:
    case Verdict::Crash: break;
    }
    return Verdict::Error;
}

QString psnrText(const GradeRow &row)
{
    if (!checked(row))
        return {};
    const double psnr = row.findings.report.comparison.psnr;
    return std::isfinite(psnr) ? QString::number(psnr, 'f', 2) : QStringLiteral("inf");
}

QString alsoText(const GradeRow &row)
{
    QStringList keys;
    if (const MistakeFinding *f = topFinding(row))
        for (ShaderMistake m : f->also)
            keys << shaderMistakeKey(m);
    return keys.join(QLatin1Char(' '));
}

// As `check` prints them: empty where every name is PhongLab's own, else
// every binding, so a teacher sees how a student's names were read.
QString bindingsCell(const GradeRow &row)
{
    return bindingsText(row.findings.bindings).replace(QStringLiteral(", "), QStringLiteral(" "));
}

// grade --pages: the fidelity's largest difference, the own scene's
// verdict, the JavaScript half's mistakes ("ok" where it has none), and
// why the page could not be run.
QStringList pageCells(const SubmissionPage *page)
{
    if (!page)
        return {QString(), QString(), QString(), QString()};
    if (!page->error.isEmpty())
        return {QString(), QString(), QString(), textCell(page->error)};
    return {page->largestDifference ? QString::number(*page->largestDifference) : QString(),
            page->ownScene,
            page->mistakes.isEmpty() ? QStringLiteral("ok")
                                     : textCell(page->mistakes.join(QLatin1Char(' '))),
            QString()};
}

QStringList csvRecord(const GradeResults &results, const GradeRow &row)
{
    const CheckReport &r = row.findings.report;
    const RowPlace place = rowPlace(row);
    return QStringList{textCell(results.submissions[std::size_t(row.submission)].name),
                       textCell(results.scenes[std::size_t(row.scene)].label),
                       verdictName(row.verdict),
                       psnrText(row),
                       checked(row) ? QString::number(r.comparison.maxError) : QString(),
                       checked(row) ? QString::number(r.badFraction(), 'f', 6) : QString(),
                       rowMistakeKey(row),
                       alsoText(row),
                       textCell(place.file),
                       place.file.isEmpty() || place.line <= 0 ? QString()
                                                               : QString::number(place.line),
                       checked(row) ? phongEquationKey(r.equation) : QString(),
                       textCell(bindingsCell(row)),
                       QString::number(row.seconds, 'f', 2),
                       rowMistakeKeys(row),
                       textCell(results.submissions[std::size_t(row.submission)].program),
                       textCell(results.submissions[std::size_t(row.submission)].student),
                       textCell(results.submissions[std::size_t(row.submission)].participant)}
    + pageCells(results.pageOf(row));
}

} // namespace

QByteArray gradesCsv(const GradeResults &results)
{
    QString out = csvColumns().join(QLatin1Char(',')) + QLatin1Char('\n');
    for (const GradeRow &row : results.rows)
        out += csvRecord(results, row).join(QLatin1Char(',')) + QLatin1Char('\n');
    return out.toUtf8();
}

QJsonObject gradesJson(const GradeResults &results)
{
    QJsonArray scenes;
    for (const GradeScene &s : results.scenes)
        scenes.append(
            QJsonObject{{QStringLiteral("label"), s.label}, {QStringLiteral("path"), s.path}});
    QJsonArray rows;
    for (const GradeRow &row : results.rows) {
        QJsonObject o = checkJson(checkVerdict(row.verdict), row.findings);
        o.insert(QStringLiteral("verdict"), verdictName(row.verdict));
        o.insert(QStringLiteral("submission"),
                 results.submissions[std::size_t(row.submission)].name);
        const Submission &submission = results.submissions[std::size_t(row.submission)];
        o.insert(QStringLiteral("program"), submission.program);
        o.insert(QStringLiteral("student"), submission.student);
        o.insert(QStringLiteral("participant"), submission.participant);
        o.insert(QStringLiteral("scene"), results.scenes[std::size_t(row.scene)].label);
        o.insert(QStringLiteral("seconds"), row.seconds);
        if (const SubmissionPage *page = results.pageOf(row))
            o.insert(QStringLiteral("page"), page->json);
        rows.append(o);
    }
    return {{QStringLiteral("scenes"), scenes}, {QStringLiteral("rows"), rows}};
}

QString gradesTable(const GradeResults &results)
{
    // Names as typed, cut to keep the columns: a terminal is no place for a
    // 200-character folder name.
    const auto cut = [](const QString &text, int width) {
        QString clean = text;
        for (QChar &c : clean)
            if (c.category() == QChar::Other_Control)
                c = QLatin1Char('?');
        return clean.size() <= width ? clean : clean.left(width - 1) + QChar(0x2026);
    };
    // A course platform's student by their name; a project's program beside
    // it where the student handed in several.
    QHash<QString, int> programs;
    for (const Submission &s : results.submissions)
        ++programs[s.name];
    const auto shownName = [&](const Submission &s) {
        const QString who = s.student.isEmpty() ? s.name : s.student;
        return programs.value(s.name) < 2 ? who : QStringLiteral("%1 (%2)").arg(who, s.program);
    };
    // The table's head: the verdicts below it are keys, as in grades.csv.
    const QString nameHead = GradeTablesWords::tr("student");
    const QString sceneHead = GradeTablesWords::tr("scene");
    int nameWidth = std::max(7, int(nameHead.size()));
    int sceneWidth = std::max(5, int(sceneHead.size()));
    for (const Submission &s : results.submissions)
        nameWidth = std::clamp(int(shownName(s).size()), nameWidth, 24);
    for (const GradeScene &s : results.scenes)
        sceneWidth = std::clamp(int(s.label.size()), sceneWidth, 20);
    // Padded by hand: arg() again after a student's name would fill a "%2" in it.
    const auto line = [&](const QString &name, const QString &scene, const QString &verdict,
                          const QString &psnr, const QString &what) {
        QString text = name.leftJustified(nameWidth) + QStringLiteral("  ")
            + scene.leftJustified(sceneWidth) + QStringLiteral("  ") + verdict.leftJustified(7)
            + QStringLiteral("  ") + psnr.rightJustified(7) + QStringLiteral("  ") + what;
        while (text.endsWith(QLatin1Char(' ')))
            text.chop(1);
        return text;
    };
    QStringList lines{line(nameHead, sceneHead, GradeTablesWords::tr("verdict"),
                           GradeTablesWords::tr("PSNR dB"),
                           GradeTablesWords::tr("mistake, where"))};
    int previous = -1;
    for (const GradeRow &row : results.rows) {
        const QString name = row.submission == previous
            ? QString()
            : cut(shownName(results.submissions[std::size_t(row.submission)]), nameWidth);
        previous = row.submission;
        QString what = rowMistakeKeys(row).replace(QLatin1Char(' '), QLatin1Char('+'));
        if (!checked(row) && !row.findings.errors.empty())
            what = cut(row.findings.errors.front().message, 60);
        const RowPlace place = rowPlace(row);
        if (!place.file.isEmpty())
            what += (what.isEmpty() ? QString() : QStringLiteral("  ")) + cut(place.file, 40)
                + (place.line > 0 ? QStringLiteral(":") + QString::number(place.line) : QString());
        lines << line(name, cut(results.scenes[std::size_t(row.scene)].label, sceneWidth),
                      verdictName(row.verdict), psnrText(row), what);
    }
    return lines.join(QLatin1Char('\n'));
}

} // namespace phonglab::cli
