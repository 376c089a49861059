#include "PageCheckOutput.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <cmath>

namespace phonglab {

struct PageCheckOutputWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PageCheckOutput)
};

namespace {

QString key(const char *name)
{
    return QString::fromLatin1(name);
}

// What a page said, for a terminal or a text box: its control characters
// (an escape sequence, a carriage return) as spaces.
QString plain(QString text)
{
    for (QChar &c : text)
        if (c.category() == QChar::Other_Control)
            c = QLatin1Char(' ');
    return text;
}

QJsonArray stringArray(const QStringList &list)
{
    return QJsonArray::fromStringList(list);
}

QJsonObject fidelityJson(const PageCheck &check)
{
    if (!check.fidelity)
        return {{key("error"), check.fidelityError}};
    const PageFidelity &f = *check.fidelity;
    return {{key("faithful"), f.faithful() && check.notReplayed.isEmpty()},
            {key("largest_difference"), f.largestOutsideEdges},
            {key("largest_anywhere"), f.largestAnywhere},
            {key("edge_pixels"), f.edgePixels},
            {key("differing_pixels"), f.differingOutsideEdges},
            {key("tolerance"), kFidelityToleranceSteps},
            {key("worst"), f.worst.x() < 0 ? QJsonValue() : QJsonArray{f.worst.x(), f.worst.y()}},
            {key("not_replayed"), stringArray(check.notReplayed)}};
}

QJsonArray linesJson(const PageCheck &check)
{
    QJsonArray out;
    for (const auto &[mistake, line] : check.ownSceneLines)
        out.append(QJsonObject{{key("mistake"), mistake},
                               {key("file"), line.file},
                               {key("line"), line.line},
                               {key("text"), line.text}});
    return out;
}

QJsonObject ownSceneJson(const PageCheck &check)
{
    if (!check.ownScene)
        return {{key("checked"), false}, {key("why"), check.ownSceneWhy}};
    const CheckReport &r = *check.ownScene;
    QJsonArray mistakes;
    for (const MistakeFinding &f : r.diagnosis.findings)
        mistakes.append(shaderMistakeKey(f.key));
    return {
        {key("checked"), true},
        {key("verdict"), r.passed() ? key("pass") : key("fail")},
        {key("psnr_db"),
         std::isfinite(r.comparison.psnr) ? QJsonValue(r.comparison.psnr) : QJsonValue(key("inf"))},
        {key("max_error"), r.comparison.maxError},
        {key("bad_fraction"), r.badFraction()},
        {key("mistakes"), mistakes},
        {key("lines"), linesJson(check)},
        {key("summary"), checkSummary(r)}};
}

} // namespace

QJsonObject pageJson(const PageCheck &check)
{
    if (!check.ok())
        return {{key("error"), check.error}};
    const PageCapture &c = check.capture;
    QJsonArray steps;
    for (const PageStep &s : c.steps)
        steps.append(QJsonObject{{key("step"), s.step}, {key("problem"), s.problem}});
    QJsonArray javascript;
    for (const JavaScriptFinding &f : check.javascript)
        javascript.append(QJsonObject{{key("key"), f.key},
                                      {key("subject"), f.subject},
                                      {key("mistake"), f.mistake},
                                      {key("message"), f.message},
                                      {key("where"), f.where}});
    return {{key("file"), c.page},
            {key("webgl"), c.webgl},
            {key("frame"), c.frame},
            {key("animated"), c.animated},
            {key("canvas"), QJsonArray{c.canvas.width(), c.canvas.height()}},
            {key("milliseconds"), check.milliseconds},
            {key("steps"), steps},
            {key("served"), stringArray(c.served)},
            {key("refused"), stringArray(c.refused)},
            {key("errors"), stringArray(c.errors)},
            {key("console_errors"), stringArray(c.consoleErrors)},
            {key("fidelity"), fidelityJson(check)},
            {key("javascript"), javascript},
            {key("own_scene"), ownSceneJson(check)},
            {key("mesh_errors"), stringArray(check.meshErrors)}};
}

QStringList pageText(const PageCheck &check)
{
    if (!check.ok())
        return {PageCheckOutputWords::tr("page: not run: %1").arg(check.error)};
    const PageCapture &c = check.capture;
    QStringList lines;
    lines << PageCheckOutputWords::tr("page: %1, WebGL %2, frame %3 of a %4x%5 canvas%6")
                 .arg(c.page)
                 .arg(c.webgl)
                 .arg(c.frame)
                 .arg(c.canvas.width())
                 .arg(c.canvas.height())
                 .arg(check.milliseconds > 0
                          ? QStringLiteral(" (%1 s)").arg(check.milliseconds / 1000.0, 0, 'f', 1)
                          : QString());
    for (const PageStep &s : c.steps)
        if (!s.problem.isEmpty())
            lines << PageCheckOutputWords::tr("page step '%1': %2")
                         .arg(plain(s.step), plain(s.problem));
    for (const QString &r : c.refused)
        lines << PageCheckOutputWords::tr("refused (the page gets no network): %1").arg(plain(r));
    for (const QString &e : c.errors + c.consoleErrors)
        lines << PageCheckOutputWords::tr("page error: %1").arg(plain(e));
    if (check.fidelity)
        lines << (check.fidelity->faithful() && check.notReplayed.isEmpty()
                      ? PageCheckOutputWords::tr(
                            "fidelity: PhongLab draws the page's frame as the "
                            "browser did (largest difference %1 outside edges)")
                            .arg(check.fidelity->largestOutsideEdges)
                      : PageCheckOutputWords::tr(
                            "fidelity: PhongLab does not draw the page's frame as "
                            "the browser did (largest difference %1 outside "
                            "edges): what follows may be PhongLab's mistake, "
                            "not the student's")
                            .arg(check.fidelity->largestOutsideEdges));
    else
        lines << PageCheckOutputWords::tr("fidelity: not checked: %1").arg(check.fidelityError);
    for (const QString &n : check.notReplayed)
        lines << PageCheckOutputWords::tr("not drawn again: %1").arg(n);
    for (const JavaScriptFinding &f : check.javascript)
        lines << (f.where.isEmpty() ? QString() : plain(f.where) + QStringLiteral(": "))
                + (f.mistake ? PageCheckOutputWords::tr("javascript: %1")
                             : PageCheckOutputWords::tr("javascript ok: %1"))
                      .arg(f.message);
    for (const QString &e : check.meshErrors)
        lines << PageCheckOutputWords::tr("course mesh not read: %1").arg(e);
    lines << (check.ownScene
                  ? PageCheckOutputWords::tr("own scene: %1").arg(checkSummary(*check.ownScene))
                  : PageCheckOutputWords::tr("own scene: not checked: %1").arg(check.ownSceneWhy));
    for (const auto &[mistake, line] : check.ownSceneLines)
        lines << QStringLiteral("  %1:%2: %3 (%4)")
                     .arg(line.file)
                     .arg(line.line)
                     .arg(plain(line.text), mistake);
    return lines;
}

} // namespace phonglab
