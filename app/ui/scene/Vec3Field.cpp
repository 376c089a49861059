#include "Vec3Field.h"

#include <QColorDialog>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <algorithm>
#include <cmath>

namespace phonglab {

namespace {

constexpr int kDecimals = 4;

// "nan" and "inf" must reach the range check as themselves, so parse with
// the C locale, which knows them, after trying the user's own.
bool parseNumber(const QString &text, double *value)
{
    bool ok = false;
    *value = QLocale().toDouble(text.trimmed(), &ok);
    if (!ok)
        *value = QLocale::c().toDouble(text.trimmed(), &ok);
    if (!ok) {
        const QString t = text.trimmed().toLower();
        if (t == QLatin1String("nan") || t == QLatin1String("inf") || t == QLatin1String("-inf")) {
            *value = t == QLatin1String("nan") ? std::nan("")
                                               : (t.startsWith('-') ? -INFINITY : INFINITY);
            ok = true;
        }
    }
    return ok;
}

} // namespace

Vec3Field::Vec3Field(double minimum, double maximum, QWidget *parent)
    : QWidget(parent)
    , m_error(new QLabel(this))
    , m_minimum(minimum)
    , m_maximum(maximum)
{
    auto *layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    for (int axis = 0; axis < 3; ++axis) {
        m_edits[axis] = new QLineEdit(this);
        m_edits[axis]->setMinimumWidth(50);
        connect(m_edits[axis], &QLineEdit::editingFinished, this, &Vec3Field::commit);
        layout->addWidget(m_edits[axis], 0, axis);
    }
    m_error->setStyleSheet(QStringLiteral("color: #d04040"));
    m_error->setWordWrap(true);
    m_error->hide();
    layout->addWidget(m_error, 1, 0, 1, 4);
    showValue();
}

void Vec3Field::enableColourPicker()
{
    m_colour = new QPushButton(tr("…"), this);
    m_colour->setToolTip(tr("Pick as a colour"));
    m_colour->setMaximumWidth(28);
    connect(m_colour, &QPushButton::clicked, this, &Vec3Field::pickColour);
    static_cast<QGridLayout *>(layout())->addWidget(m_colour, 0, 3);
}

void Vec3Field::setValue(const glm::dvec3 &value)
{
    m_value = value;
    showValue();
}

void Vec3Field::showValue()
{
    for (int axis = 0; axis < 3; ++axis)
        m_edits[axis]->setText(QLocale().toString(m_value[axis], 'g', kDecimals + 2));
    if (m_colour) {
        const QColor c = QColor::fromRgbF(float(std::clamp(m_value.r, 0.0, 1.0)),
                                          float(std::clamp(m_value.g, 0.0, 1.0)),
                                          float(std::clamp(m_value.b, 0.0, 1.0)));
        m_colour->setStyleSheet(QStringLiteral("background-color: %1").arg(c.name()));
    }
}

QString Vec3Field::errorText() const
{
    return m_error->isHidden() ? QString() : m_error->text();
}

QString Vec3Field::parse(glm::dvec3 *parsed) const
{
    static const char *names[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        double v = 0.0;
        if (!parseNumber(m_edits[axis]->text(), &v))
            return tr("%1: \"%2\" is not a number").arg(names[axis], m_edits[axis]->text());
        if (std::isnan(v))
            return tr("%1: NaN is not allowed").arg(names[axis]);
        if (!std::isfinite(v))
            return tr("%1: must be finite").arg(names[axis]);
        if (v < m_minimum || v > m_maximum)
            return tr("%1: must be in [%2, %3] (got %4)")
                .arg(names[axis])
                .arg(m_minimum)
                .arg(m_maximum)
                .arg(v);
        (*parsed)[axis] = v;
    }
    return m_check ? m_check(*parsed) : QString();
}

bool Vec3Field::commit()
{
    glm::dvec3 parsed = m_value;
    const QString reason = parse(&parsed);
    if (!reason.isEmpty()) {
        refuse(reason);
        return false;
    }
    m_error->hide();
    m_error->clear();
    if (parsed == m_value)
        return true;
    const glm::dvec3 before = m_value;
    setValue(parsed);
    emit edited(before, parsed);
    return true;
}

void Vec3Field::refuse(const QString &reason)
{
    m_error->setText(reason);
    m_error->show();
    showValue(); // the last valid value stays
}

void Vec3Field::pickColour()
{
    const QColor start = QColor::fromRgbF(float(m_value.r), float(m_value.g), float(m_value.b));
    const QColor chosen = QColorDialog::getColor(start, this);
    if (!chosen.isValid())
        return;
    const glm::dvec3 picked{chosen.redF(), chosen.greenF(), chosen.blueF()};
    for (int axis = 0; axis < 3; ++axis)
        m_edits[axis]->setText(QLocale().toString(picked[axis], 'g', kDecimals + 2));
    commit();
}

} // namespace phonglab
