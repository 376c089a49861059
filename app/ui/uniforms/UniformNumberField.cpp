#include "UniformNumberField.h"

#include <QTimer>
#include <cmath>
#include <limits>

namespace phonglab {

UniformNumberField::UniformNumberField(QWidget *parent)
    : QDoubleSpinBox(parent)
{
    setDecimals(4);
    setKeyboardTracking(false); // a value is taken on Enter / focus out, not per keystroke
    setCorrectionMode(QAbstractSpinBox::CorrectToPreviousValue);
    connect(this, &QDoubleSpinBox::valueChanged, this, [this] { clearRefusal(); });
}

std::optional<double> UniformNumberField::parse(const QString &text) const
{
    QString t = text.trimmed();
    if (!prefix().isEmpty() && t.startsWith(prefix()))
        t.remove(0, prefix().size());
    if (!suffix().isEmpty() && t.endsWith(suffix()))
        t.chop(suffix().size());
    bool ok = false;
    double value = locale().toDouble(t, &ok);
    if (!ok)
        value = t.toDouble(&ok); // "0.5" also where the locale writes "0,5"
    if (!ok)
        return std::nullopt;
    return value;
}

QString UniformNumberField::reasonToRefuse(const QString &text) const
{
    const std::optional<double> value = parse(text);
    if (!value)
        return tr("“%1” is not a number").arg(text.trimmed());
    if (std::isnan(*value))
        return tr("not a number (NaN)");
    if (!std::isfinite(*value))
        return tr("not a finite number");
    if (*value < minimum() || *value > maximum())
        return tr("%1 is outside the range %2 … %3").arg(*value).arg(minimum()).arg(maximum());
    return {};
}

QValidator::State UniformNumberField::validate(QString &input, int &) const
{
    // Intermediate, never Invalid: the user may type "nan" and be told why
    // it is refused when editing ends (fixup) rather than have keys ignored.
    return reasonToRefuse(input).isEmpty() ? QValidator::Acceptable : QValidator::Intermediate;
}

void UniformNumberField::fixup(QString &input) const
{
    // QAbstractSpinBox calls this when editing ends on unacceptable text and
    // then puts the previous value back; the mark is set once that is done.
    const QString reason = reasonToRefuse(input);
    if (reason.isEmpty())
        return;
    auto *self = const_cast<UniformNumberField *>(this);
    QTimer::singleShot(0, self, [self, reason] { self->showRefusal(reason); });
}

double UniformNumberField::valueFromText(const QString &text) const
{
    return parse(text).value_or(value());
}

void UniformNumberField::showRefusal(const QString &reason)
{
    if (!m_showingRefusal)
        m_plainToolTip = toolTip();
    m_showingRefusal = true;
    m_refusal = reason;
    setStyleSheet(QStringLiteral("QDoubleSpinBox { border: 2px solid #d32f2f; }"));
    setToolTip(tr("Refused: %1. The value stays %2.").arg(reason, textFromValue(value())));
    emit refused(reason);
}

void UniformNumberField::clearRefusal()
{
    if (!m_showingRefusal)
        return;
    m_showingRefusal = false;
    m_refusal.clear();
    setStyleSheet({});
    setToolTip(m_plainToolTip);
}

} // namespace phonglab
