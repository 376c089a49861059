#pragma once
#include <QLabel>

namespace phonglab {

// The status bar's verdict: the short form of the check's panel, cut at a
// whole word with "…" where the bar is narrower than it (never "N·" of
// "N·L"), its whole text in the tooltip. A click asks for the way on: the
// row of a uniform to place, or the check's panel.
class VerdictLabel : public QLabel
{
    Q_OBJECT

public:
    explicit VerdictLabel(QWidget *parent = nullptr);

    void setVerdict(const QString &text);
    QString verdict() const { return m_full; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void clicked();

protected:
    void resizeEvent(QResizeEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;

private:
    void elide();

    QString m_full;
};

// `text` as far as whole words fit in `width` pixels, "…" after the last;
// `text` itself where it fits.
QString wordElided(const QString &text, const QFontMetrics &metrics, int width);

} // namespace phonglab
