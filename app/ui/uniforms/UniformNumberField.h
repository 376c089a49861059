#pragma once
#include <QDoubleSpinBox>
#include <optional>

namespace phonglab {

// A QDoubleSpinBox that refuses bad input visibly instead of silently: any
// text may be typed, and when editing ends on something that is not a
// finite number inside [minimum, maximum] (NaN, inf, 5 for a 0..2 range)
// the field keeps its last valid value, turns red and says why (tooltip and
// refused()). The next accepted value clears the mark.
class UniformNumberField : public QDoubleSpinBox
{
    Q_OBJECT

public:
    explicit UniformNumberField(QWidget *parent = nullptr);

    // Why the last input was refused; empty after an accepted one.
    QString refusal() const { return m_refusal; }
    // Empty when `text` is acceptable, else the reason it is not.
    QString reasonToRefuse(const QString &text) const;

    QValidator::State validate(QString &input, int &pos) const override;
    void fixup(QString &input) const override;
    double valueFromText(const QString &text) const override;

signals:
    void refused(const QString &reason);

private:
    std::optional<double> parse(const QString &text) const;
    void showRefusal(const QString &reason);
    void clearRefusal();

    QString m_refusal;
    QString m_plainToolTip; // the tooltip to put back once the input is good
    bool m_showingRefusal = false;
};

} // namespace phonglab
