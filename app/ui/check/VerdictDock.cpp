#include "VerdictDock.h"

#include "render/check/CheckReportOutput.h"

#include <QRegularExpression>
#include <QTextBrowser>
#include <QUrl>

namespace phonglab {

namespace {

QString unboundNames(const std::vector<UnboundUniform> &unbound)
{
    QStringList names;
    for (const UnboundUniform &u : unbound)
        names << u.name;
    return names.join(QObject::tr(", "));
}

// The stage a "FILE:LINE: text" line of the report points into: the stage
// of that name whose line says the same (both stages of a page share a file).
std::optional<ShaderStage> stageOfLine(const std::vector<ShaderStageText> &stages,
                                       const QString &file, int line, const QString &text)
{
    std::optional<ShaderStage> named;
    for (const ShaderStageText &s : stages) {
        if (s.path != file)
            continue;
        const ShaderStage stage = s.vertex ? ShaderStage::Vertex : ShaderStage::Fragment;
        if (s.text.split(QLatin1Char('\n')).value(line - 1).trimmed() == text)
            return stage;
        named = stage;
    }
    return named;
}

// One line of checkText(), escaped, its source line a link to the editor.
QString reportLineHtml(const QString &line, const std::vector<ShaderStageText> &stages)
{
    static const QRegularExpression sourceLine(QStringLiteral(R"(^(\s+)(.+):(\d+): (.*)$)"));
    const QRegularExpressionMatch m = sourceLine.match(line);
    if (m.hasMatch()) {
        const int number = m.captured(3).toInt();
        if (const auto stage = stageOfLine(stages, m.captured(2), number, m.captured(4).trimmed()))
            return QStringLiteral("%1<a href=\"line:%2:%3\">%4:%3</a>: <code>%5</code>")
                .arg(m.captured(1), stageName(*stage))
                .arg(number)
                .arg(m.captured(2).toHtmlEscaped(), m.captured(4).toHtmlEscaped());
    }
    return line.toHtmlEscaped();
}

QString errorsHtml(const CheckedFrame &result)
{
    QString html;
    if (!result.error.isEmpty())
        html +=
            QStringLiteral("<div style=\"color:#c62828\">%1</div>")
                .arg(QObject::tr("The check could not run: %1").arg(result.error).toHtmlEscaped());
    for (const ShaderDiagnostic &e : result.outcome.errors)
        html +=
            QStringLiteral("<div style=\"color:#c62828\">%1</div>").arg(e.message.toHtmlEscaped());
    for (const UnboundUniform &u : result.unbound)
        html +=
            QStringLiteral("<div>→ <a href=\"uniform:%1\">%2</a></div>")
                .arg(QString::fromUtf8(QUrl::toPercentEncoding(u.name)),
                     QObject::tr("choose what %1 means in Uniforms").arg(u.name).toHtmlEscaped());
    return html;
}

} // namespace

QString verdictStatusText(const CheckedFrame &result, bool current)
{
    QString text;
    if (!result.error.isEmpty())
        text = QObject::tr("check: %1").arg(result.error);
    else if (!result.unbound.empty())
        text = QObject::tr("no verdict: choose what %1 %2 in Uniforms")
                   .arg(unboundNames(result.unbound),
                        result.unbound.size() == 1 ? QObject::tr("means") : QObject::tr("mean"));
    else if (!result.hasVerdict())
        text = QObject::tr("no verdict: %1")
                   .arg(result.outcome.errors.empty() ? QObject::tr("see the check's panel")
                                                      : result.outcome.errors.front().message);
    else {
        text = checkStatusLine(result.report());
        // Gouraud, flat and faceted are approximations by design: say what
        // they are checked against.
        const ShadingMethod method = result.scene.shading;
        if (method == ShadingMethod::Gouraud || method == ShadingMethod::Flat
            || method == ShadingMethod::Faceted)
            text = QObject::tr("%1 against exact Phong: %2").arg(shadingName(method), text);
    }
    return current ? text : QObject::tr("last good program: %1").arg(text);
}

VerdictDock::VerdictDock(QWidget *parent)
    : QDockWidget(tr("Check"), parent)
    , m_text(new QTextBrowser(this))
{
    setObjectName(QStringLiteral("verdictDock"));
    m_text->setObjectName(QStringLiteral("verdictText"));
    m_text->setOpenLinks(false);
    m_text->setPlaceholderText(
        tr("The check's verdict appears here once the first frame is checked."));
    setWidget(m_text);
    connect(m_text, &QTextBrowser::anchorClicked, this, [this](const QUrl &url) {
        const QString link = url.toString(QUrl::FullyDecoded);
        if (link.startsWith(QLatin1String("uniform:"))) {
            emit uniformChosen(link.mid(8));
            return;
        }
        const QStringList parts = link.split(QLatin1Char(':'));
        if (parts.size() == 3 && parts[0] == QLatin1String("line"))
            emit lineChosen(parts[1] == stageName(ShaderStage::Vertex) ? ShaderStage::Vertex
                                                                       : ShaderStage::Fragment,
                            parts[2].toInt());
    });
}

void VerdictDock::showVerdict(const CheckedFrame &result, bool current)
{
    QString html =
        QStringLiteral("<p><b>%1</b></p>").arg(verdictStatusText(result, current).toHtmlEscaped());
    if (!current)
        html += QStringLiteral("<p><i>%1</i></p>")
                    .arg(tr("The code in the editor does not compile: this is the verdict of the "
                            "last program that did, which is still drawn.")
                             .toHtmlEscaped());
    html += errorsHtml(result);
    if (result.error.isEmpty()) {
        for (const QString &line : checkText(result.outcome, result.scene).split(QLatin1Char('\n')))
            html += QStringLiteral("<div style=\"white-space:pre-wrap\">%1</div>")
                        .arg(reportLineHtml(line, result.outcome.stages));
    }
    m_text->setHtml(html);
}

QString VerdictDock::text() const
{
    return m_text->toPlainText();
}

} // namespace phonglab
