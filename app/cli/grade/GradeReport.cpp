#include "GradeReport.h"

#include "core/support/Language.h"
#include <QCoreApplication>
#include <QJsonArray>

#include "core/scene/ResourcePaths.h"

#include <QFileInfo>
#include <QRegularExpression>

#include <cmath>
#include <map>

namespace phonglab::cli {

// The report's words, in the language of the run (core/support/Language); what
// students wrote is escaped as before.
struct ReportWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::GradeReport)
};

namespace {

QString esc(const QString &text)
{
    return text.toHtmlEscaped();
}

// Worst first: what a teacher looks at before the passes.
int verdictRank(Verdict v)
{
    switch (v) {
    case Verdict::Crash: return 0;
    case Verdict::Timeout: return 1;
    case Verdict::Error: return 2;
    case Verdict::Fail: return 3;
    case Verdict::Pass: return 4;
    }
    return 2;
}

constexpr Verdict kVerdicts[] = {Verdict::Pass, Verdict::Fail, Verdict::Error, Verdict::Timeout,
                                 Verdict::Crash};

QString verdictColour(Verdict v)
{
    switch (v) {
    case Verdict::Pass: return QStringLiteral("#2e7d32");
    case Verdict::Fail: return QStringLiteral("#c62828");
    case Verdict::Error: return QStringLiteral("#ef6c00");
    case Verdict::Timeout: return QStringLiteral("#6a1b9a");
    case Verdict::Crash: return QStringLiteral("#37474f");
    }
    return QStringLiteral("#000");
}

const char *kStyle = R"(
body{font:14px/1.4 system-ui,sans-serif;margin:24px;color:#212121}
h1{font-size:20px}h2{font-size:16px;margin-top:28px}
table.rows{border-collapse:collapse;width:100%}
table.rows th,table.rows td{border-top:1px solid #ddd;padding:6px;vertical-align:top;text-align:left}
table.rows th.sortable{cursor:pointer;text-decoration:underline dotted}
.verdict{font-weight:bold;color:#fff;padding:1px 6px;border-radius:3px}
td.images{white-space:nowrap}td.why{min-width:320px;max-width:640px}
.images img{width:160px;image-rendering:pixelated;border:1px solid #ccc}
.images figure{display:inline-block;margin:0 4px 0 0}.images figcaption{font-size:12px;color:#555}
pre.lines{background:#f6f6f6;padding:4px 6px;margin:4px 0;white-space:pre-wrap;overflow-wrap:anywhere}
pre.lines .hit{background:#ffe0b2;display:block}
code.command{display:block;user-select:all;background:#eef;padding:3px 6px;word-break:break-all}
#missing{display:none;background:#ffebee;padding:8px;border:1px solid #c62828}
.legend span{display:inline-block;width:10px;height:10px;margin:0 4px 0 12px}
)";

const char *kScript = R"(
(function(){
  var rank={student:function(r){return r.dataset.student;},
            verdict:function(r){return r.dataset.rank+'\u0000'+r.dataset.student;},
            psnr:function(r){return parseFloat(r.dataset.psnr);}};
  function sortBy(key){
    var body=document.querySelector('table.rows tbody');
    var rows=Array.prototype.slice.call(body.rows);
    rows.sort(function(a,b){var x=rank[key](a),y=rank[key](b);
      if(x<y)return -1;if(x>y)return 1;return a.dataset.order-b.dataset.order;});
    rows.forEach(function(r){body.appendChild(r);});
    document.body.dataset.sortedBy=key;
  }
  document.querySelectorAll('th[data-sort]').forEach(function(th){
    th.addEventListener('click',function(){sortBy(th.dataset.sort);});});
  var m=/sort=(\w+)/.exec(location.hash);if(m&&rank[m[1]])sortBy(m[1]);
  window.addEventListener('load',function(){
    var broken=Array.prototype.filter.call(document.images,function(i){return !i.naturalWidth;});
    document.body.dataset.brokenImages=broken.length;
    if(broken.length){var w=document.getElementById('missing');w.style.display='block';
      w.textContent=broken.length+' image(s) cannot be shown: keep the images folder beside report.html.';}
  });
})();
)";

QString bar(double fraction, const QString &colour, int width = 300)
{
    const int px = int(std::lround(std::clamp(fraction, 0.0, 1.0) * width));
    return QStringLiteral("<rect x=\"%1\" width=\"%2\" height=\"14\" fill=\"%3\"/>")
        .arg(0)
        .arg(px)
        .arg(colour);
}

QString verdictBadge(Verdict v)
{
    return QStringLiteral("<span class=\"verdict\" style=\"background:%1\">%2</span>")
        .arg(verdictColour(v), verdictName(v));
}

QString summary(const GradeResults &results)
{
    QString html =
        QStringLiteral("<h2>%1</h2><table>").arg(esc(ReportWords::tr("Passes per scene")));
    const int students = int(results.submissions.size());
    for (std::size_t s = 0; s < results.scenes.size(); ++s) {
        std::map<Verdict, int> counts;
        for (const GradeRow &row : results.rows)
            if (row.scene == int(s))
                ++counts[row.verdict];
        QString rects;
        double x = 0;
        QStringList parts;
        for (Verdict v : kVerdicts) {
            const int n = counts[v];
            if (n == 0)
                continue;
            const double w = 400.0 * n / std::max(1, students);
            rects +=
                QStringLiteral("<rect x=\"%1\" width=\"%2\" height=\"16\" fill=\"%3\"><title>%4 "
                               "%5</title></rect>")
                    .arg(x, 0, 'f', 1)
                    .arg(w, 0, 'f', 1)
                    .arg(verdictColour(v))
                    .arg(n)
                    .arg(verdictName(v));
            x += w;
            parts << QStringLiteral("%1 %2").arg(n).arg(verdictName(v));
        }
        const QString passes =
            ReportWords::tr("%1 of %2 pass").arg(counts[Verdict::Pass]).arg(students);
        html += QStringLiteral("<tr><td>%1</td><td><svg width=\"400\" height=\"16\" role=\"img\" "
                               "aria-label=\"%2\">%3</svg></td><td>%4 · %2</td></tr>")
                    .arg(esc(results.scenes[s].label), esc(parts.join(QStringLiteral(", "))), rects,
                         esc(passes));
    }
    html += QStringLiteral("</table><p class=\"legend\">");
    for (Verdict v : kVerdicts)
        html += QStringLiteral("<span style=\"background:%1\"></span>%2")
                    .arg(verdictColour(v), verdictName(v));
    html += QStringLiteral("</p>");

    std::map<QString, int> mistakes;
    for (const GradeRow &row : results.rows)
        for (const QString &key : rowMistakeKeys(row).split(QLatin1Char(' '), Qt::SkipEmptyParts))
            ++mistakes[key];
    std::vector<std::pair<QString, int>> sorted(mistakes.begin(), mistakes.end());
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto &a, const auto &b) { return a.second > b.second; });
    html += QStringLiteral("<h2>%1</h2>").arg(esc(ReportWords::tr("Most common mistakes")));
    if (sorted.empty())
        return html
            + QStringLiteral("<p>%1</p>").arg(esc(ReportWords::tr("None: no check failed.")));
    const int most = sorted.front().second;
    html += QStringLiteral("<table>");
    for (const auto &[key, n] : sorted)
        html += QStringLiteral("<tr><td>%1</td><td><svg width=\"300\" height=\"14\" "
                               "role=\"img\" aria-label=\"%2\">%3</svg></td><td>%2</td></tr>")
                    .arg(esc(key), QString::number(n),
                         bar(double(n) / most, QStringLiteral("#c62828")));
    return html + QStringLiteral("</table>");
}

// The stage text a line or error points into: by the path the row reports
// and, where both stages sit in one page (a WebGL project), the one that
// has text on that line.
const ShaderStageText *stageText(const GradeRow &row, const QString &file, int line)
{
    const ShaderStageText *found = nullptr;
    for (const ShaderStageText &s : row.findings.stages) {
        if (s.path != file)
            continue;
        if (!found)
            found = &s;
        const QStringList lines = s.text.split(QLatin1Char('\n'));
        if (line > 0 && line <= lines.size() && !lines[line - 1].trimmed().isEmpty())
            return &s;
    }
    return found;
}

QString linesInContext(const GradeRow &row, const QString &file, int line)
{
    const ShaderStageText *stage = stageText(row, file, line);
    if (!stage || line <= 0)
        return {};
    const QStringList lines = stage->text.split(QLatin1Char('\n'));
    QString html = QStringLiteral("<pre class=\"lines\">");
    for (int l = std::max(1, line - 2); l <= std::min(int(lines.size()), line + 2); ++l) {
        const QString text = QStringLiteral("%1:%2  %3")
                                 .arg(esc(file), QStringLiteral("%1").arg(l, 4), esc(lines[l - 1]));
        html += l == line ? QStringLiteral("<span class=\"hit\">%1</span>").arg(text)
                          : text + QLatin1Char('\n');
    }
    return html + QStringLiteral("</pre>");
}

// A failed row's diagnosis: the set of mistakes that explains it together
// where there is one, else each mistake alone, with their lines.
QString diagnosisHtml(const GradeRow &row)
{
    QString html;
    const CheckFindings &o = row.findings;
    const MistakeDiagnosis &d = o.report.diagnosis;
    if (d.unexplained())
        html += QStringLiteral("<p><b>unknown</b>: %1</p>")
                    .arg(esc(ReportWords::tr("no classic mistake explains the difference; the "
                                             "heatmap shows where it is.")));
    if (d.together.variants.size() > 1 && d.together.explains >= kExplainedConfidence) {
        html += QStringLiteral("<p>%1</p><ul>")
                    .arg(esc(ReportWords::tr("%1 mistakes together explain %2 % of the "
                                             "difference:")
                                 .arg(d.together.variants.size())
                                 .arg(qRound(100.0 * d.together.explains))));
        for (MistakeVariant v : d.together.variants) {
            html += QStringLiteral("<li><b>%1</b>: %2")
                        .arg(esc(shaderMistakeKey(v.key)),
                             esc(mistakeFormSummary(v) + QStringLiteral(" — ")
                                 + shaderMistakeRule(v.key)));
            for (const SourceLine &l : mistakeSourceLines(v.key, o.stages))
                html += linesInContext(row, l.file, l.line);
            html += QStringLiteral("</li>");
        }
        html += QStringLiteral("</ul>");
    }
    for (const MistakeFinding &f : d.findings) {
        if (d.together.variants.size() > 1 && d.together.explains >= kExplainedConfidence)
            break; // each alone explains less than the set above
        // The sentence is escaped whole, then the key made bold in it.
        const QString key = esc(shaderMistakeKey(f.key));
        html += QStringLiteral("<p>%1</p>")
                    .arg(esc(ReportWords::tr("%1 explains %2 % of the difference: %3")
                                 .arg(QStringLiteral("\x01"),
                                      QString::number(qRound(100.0 * f.confidence)),
                                      shaderMistakeRule(f.key)))
                             .replace(QLatin1Char('\x01'), QStringLiteral("<b>%1</b>").arg(key)));
        for (const SourceLine &l : mistakeSourceLines(f.key, o.stages))
            html += linesInContext(row, l.file, l.line);
    }
    return html;
}

QString details(const GradeRow &row)
{
    QString html;
    const CheckFindings &o = row.findings;
    if (row.verdict == Verdict::Pass)
        html += QStringLiteral("<p>%1</p>").arg(esc(ReportWords::tr("Matches the exact image.")));
    if (row.verdict == Verdict::Fail)
        html += diagnosisHtml(row);
    for (const ShaderDiagnostic &e : o.errors) {
        html += QStringLiteral("<p>%1%2</p>")
                    .arg(e.file.isEmpty()
                             ? QString()
                             : QStringLiteral("<code>%1%2</code>: ")
                                   .arg(esc(e.file),
                                        e.line > 0 ? QStringLiteral(":%1").arg(e.line) : QString()),
                         esc(e.message));
        html += linesInContext(row, e.file, e.line);
    }
    for (const QString &note : o.notes)
        html += QStringLiteral("<p><i>%1</i> %2</p>").arg(esc(ReportWords::tr("note:")), esc(note));
    for (const QString &warning : o.warnings)
        html += QStringLiteral("<p><i>%1</i> %2</p>")
                    .arg(esc(ReportWords::tr("warning:")), esc(warning));
    if (const QString precision = precisionText(o.precision); !precision.isEmpty())
        html += QStringLiteral("<p><i>%1</i></p>").arg(esc(precision));
    return html;
}

QString figure(const QString &image, const QString &caption)
{
    if (image.isEmpty())
        return {};
    return QStringLiteral("<figure><a href=\"%1\"><img src=\"%1\" alt=\"%2\" loading=\"lazy\"></a>"
                          "<figcaption>%2</figcaption></figure>")
        .arg(esc(image), esc(caption));
}

// grade --pages: the browser's frame, PhongLab's drawing of it and their
// difference, side by side; what the JavaScript half found.
QString pageFigures(const SubmissionPage *page)
{
    if (!page)
        return {};
    return figure(page->browserImage, ReportWords::tr("the browser's"))
        + figure(page->exactImage, ReportWords::tr("exact"))
        + figure(page->heatmapImage, ReportWords::tr("heatmap"))
        + figure(page->phonglabImage, ReportWords::tr("drawn again"))
        + figure(page->differenceImage, ReportWords::tr("difference"));
}

QString pageDetails(const SubmissionPage *page)
{
    if (!page)
        return {};
    if (!page->error.isEmpty())
        return QStringLiteral("<p>%1</p>")
            .arg(esc(ReportWords::tr("The page was not run: %1").arg(page->error)));
    QString html;
    if (page->largestDifference && !page->faithful)
        html += QStringLiteral("<p>%1</p>")
                    .arg(esc(ReportWords::tr("PhongLab does not draw this page as the browser did "
                                             "(largest difference %1): its findings may be "
                                             "PhongLab's mistake.")
                                 .arg(*page->largestDifference)));
    for (const QJsonValue &f : page->json.value(QStringLiteral("javascript")).toArray()) {
        const QJsonObject o = f.toObject();
        if (!o.value(QStringLiteral("mistake")).toBool())
            continue;
        const QString where = o.value(QStringLiteral("where")).toString();
        html += QStringLiteral("<p><b>%1</b>: %2</p>")
                    .arg(esc(o.value(QStringLiteral("key")).toString()),
                         esc((where.isEmpty() ? QString() : where + QStringLiteral(": "))
                             + o.value(QStringLiteral("message")).toString()));
    }
    return html;
}

QString openCommand(const GradeResults &results, const GradeRow &row)
{
    const Submission &s = results.submissions[std::size_t(row.submission)];
    if (s.vertex.isEmpty() && s.fragment.isEmpty())
        return {};
    const GradeScene &scene = results.scenes[std::size_t(row.scene)];
    // Both stages always: a stage the student left out was checked as the
    // method's shipped one, which the window would not take by itself.
    const auto stage = [&](const QString &file, ShaderStage which) {
        return shellQuoted(file.isEmpty() ? shippedShaderPath(scene.scene.shading, which) : file);
    };
    return QStringList{
        QStringLiteral("phonglab"),   shellQuoted(QFileInfo(scene.path).absoluteFilePath()),
        QStringLiteral("--vertex"),   stage(s.vertex, ShaderStage::Vertex),
        QStringLiteral("--fragment"), stage(s.fragment, ShaderStage::Fragment)}
        .join(QLatin1Char(' '));
}

QString rowHtml(const GradeResults &results, const GradeRow &row, int order)
{
    const CheckReport &r = row.findings.report;
    const bool checked = row.verdict == Verdict::Pass || row.verdict == Verdict::Fail;
    const double psnr = checked ? r.comparison.psnr : -1.0;
    const QString student = shownSubmissionName(results.submissions[std::size_t(row.submission)]);
    const QString command = openCommand(results, row);
    // One pass of arg(): text a student wrote may hold "%1" itself.
    return QStringLiteral("<tr data-order=\"%1\" data-student=\"%2\" data-rank=\"%3\" "
                          "data-psnr=\"%4\"><td>%2</td><td>%5</td><td>%6</td><td>%7</td>"
                          "<td class=\"images\">%8</td><td class=\"why\">%9%10</td></tr>\n")
        .arg(QString::number(order), esc(student), QString::number(verdictRank(row.verdict)),
             std::isfinite(psnr) ? QString::number(psnr, 'f', 2) : QStringLiteral("1e9"),
             esc(results.scenes[std::size_t(row.scene)].label), verdictBadge(row.verdict),
             checked ? (std::isfinite(psnr) ? sentenceNumber(psnr, 'f', 1) : QStringLiteral("∞"))
                     : QString(),
             figure(row.yoursImage, ReportWords::tr("theirs"))
                 + figure(row.exactImage, ReportWords::tr("exact"))
                 + figure(row.heatmapImage, ReportWords::tr("heatmap"))
                 + pageFigures(results.pageOf(row)),
             details(row) + pageDetails(results.pageOf(row)),
             command.isEmpty()
                 ? QString()
                 : QStringLiteral("<code class=\"command\" title=\"%1\">%2</code>")
                       .arg(esc(ReportWords::tr("opens it in the window")), esc(command)));
}

} // namespace

QString shellQuoted(const QString &text)
{
    static const QRegularExpression safe(QStringLiteral(R"(^[A-Za-z0-9_@%+=:,./-]+$)"));
    if (safe.match(text).hasMatch())
        return text;
    return QLatin1Char('\'') + QString(text).replace(QLatin1Char('\''), QLatin1String("'\\''"))
        + QLatin1Char('\'');
}

QString gradeReportHtml(const GradeResults &given)
{
    // A course platform's students by name, their files as they named them.
    GradeResults results = given;
    for (GradeRow &row : results.rows)
        if (const Submission &s = results.submissions[std::size_t(row.submission)];
            !s.student.isEmpty())
            nameFilesWithin(row, s.name);
    const QString title =
        esc(ReportWords::tr("PhongLab grades: %1").arg(results.settings.classFolder));
    QString html =
        QStringLiteral("<!DOCTYPE html>\n<html lang=\"%1\"><head><meta charset=\"utf-8\">"
                       "<title>%2</title><style>%3</style></head>\n"
                       "<body>\n<h1>%2</h1>\n")
            .arg(currentLanguage(), title, QString::fromLatin1(kStyle));
    const int submissions = int(results.submissions.size());
    const int scenes = int(results.scenes.size());
    const QString counts =
        (submissions == 1 ? ReportWords::tr("%1 submission") : ReportWords::tr("%1 submissions"))
            .arg(submissions)
        + QStringLiteral(", ")
        + (scenes == 1 ? ReportWords::tr("%1 scene") : ReportWords::tr("%1 scenes")).arg(scenes);
    html += QStringLiteral("<p>%1</p>\n<div id=\"missing\"></div>\n")
                .arg(esc(ReportWords::tr("%1, %2×%3 pixels, tolerance %4/255. Sort the rows by a "
                                         "column's title.")
                             .arg(counts)
                             .arg(results.settings.size.width())
                             .arg(results.settings.size.height())
                             .arg(results.settings.toleranceSteps)));
    html += summary(results);
    html += QStringLiteral("<h2>%1</h2>\n<table class=\"rows\"><thead><tr>"
                           "<th class=\"sortable\" data-sort=\"student\">%2</th><th>%3</th>"
                           "<th class=\"sortable\" data-sort=\"verdict\">%4</th>"
                           "<th class=\"sortable\" data-sort=\"psnr\">PSNR dB</th><th>%5</th>"
                           "<th>%6</th></tr></thead>\n<tbody>\n")
                .arg(esc(ReportWords::tr("Every student and scene")),
                     esc(ReportWords::tr("student")), esc(ReportWords::tr("scene")),
                     esc(ReportWords::tr("verdict")), esc(ReportWords::tr("images")),
                     esc(ReportWords::tr("why, and the command that opens it")));
    int order = 0;
    for (const GradeRow &row : results.rows)
        html += rowHtml(results, row, order++);
    html += QStringLiteral("</tbody></table>\n<script>%1</script>\n</body></html>\n")
                .arg(QString::fromLatin1(kScript));
    return html;
}

} // namespace phonglab::cli
