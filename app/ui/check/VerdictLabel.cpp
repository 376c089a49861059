#include "VerdictLabel.h"

#include <QMouseEvent>

namespace phonglab {

QString wordElided(const QString &text, const QFontMetrics &metrics, int width)
{
    if (metrics.horizontalAdvance(text) <= width)
        return text;
    const QString ellipsis = QStringLiteral(" …");
    QString kept = text;
    while (!kept.isEmpty()) {
        const qsizetype space = kept.lastIndexOf(QLatin1Char(' '));
        if (space <= 0)
            break;
        kept.truncate(space);
        while (kept.endsWith(QLatin1Char(' ')) || kept.endsWith(QChar(0x2014))
               || kept.endsWith(QLatin1Char(':')) || kept.endsWith(QLatin1Char(',')))
            kept.chop(1);
        if (metrics.horizontalAdvance(kept + ellipsis) <= width)
            return kept + ellipsis;
    }
    return kept.isEmpty() ? ellipsis.trimmed() : kept + ellipsis;
}

VerdictLabel::VerdictLabel(QWidget *parent)
    : QLabel(parent)
{
    setCursor(Qt::PointingHandCursor);
    setTextFormat(Qt::PlainText);
}

void VerdictLabel::setVerdict(const QString &text)
{
    m_full = text;
    setToolTip(text);
    elide();
    updateGeometry();
}

QSize VerdictLabel::sizeHint() const
{
    const QSize margins(contentsMargins().left() + contentsMargins().right(), 0);
    return QSize(fontMetrics().horizontalAdvance(m_full) + 4, QLabel::sizeHint().height())
        + margins;
}

QSize VerdictLabel::minimumSizeHint() const
{
    return QSize(fontMetrics().horizontalAdvance(QStringLiteral("✗ 99.9 dB …")),
                 QLabel::minimumSizeHint().height());
}

void VerdictLabel::resizeEvent(QResizeEvent *event)
{
    QLabel::resizeEvent(event);
    elide();
}

void VerdictLabel::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton)
        emit clicked();
    QLabel::mousePressEvent(event);
}

void VerdictLabel::elide()
{
    const int width = contentsRect().width();
    const QString shown = width > 0 ? wordElided(m_full, fontMetrics(), width) : m_full;
    if (shown != text())
        setText(shown);
}

} // namespace phonglab
