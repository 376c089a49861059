#include "UniformFloatRow.h"

#include "UniformNumberField.h"

#include <QBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <algorithm>
#include <cmath>

namespace phonglab {

UniformFloatRow::UniformFloatRow(double sliderLow, double sliderHigh, double fieldLow,
                                 double fieldHigh, double step, QWidget *parent)
    : QWidget(parent)
    , m_low(sliderLow)
    , m_high(sliderHigh)
    , m_field(new UniformNumberField(this))
    , m_slider(new QSlider(Qt::Horizontal, this))
    , m_refusal(new QLabel(this))
{
    m_field->setRange(fieldLow, fieldHigh);
    m_field->setSingleStep(step);
    m_slider->setRange(0, kSliderSteps);
    m_refusal->setStyleSheet(QStringLiteral("color: #d32f2f;"));
    m_refusal->setWordWrap(true);
    m_refusal->hide();

    auto *line = new QHBoxLayout;
    line->setContentsMargins(0, 0, 0, 0);
    line->addWidget(m_slider, 1);
    line->addWidget(m_field);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(line);
    layout->addWidget(m_refusal);

    connect(m_field, &QDoubleSpinBox::valueChanged, this, &UniformFloatRow::onFieldChanged);
    connect(m_slider, &QSlider::valueChanged, this, &UniformFloatRow::onSliderMoved);
    connect(m_field, &UniformNumberField::refused, this, [this](const QString &reason) {
        m_refusal->setText(tr("Refused: %1").arg(reason));
        m_refusal->show();
    });
}

void UniformFloatRow::setValue(float value)
{
    const QSignalBlocker blockField(m_field);
    m_field->setValue(value);
    placeSlider(value);
}

float UniformFloatRow::value() const
{
    return float(m_field->value());
}

void UniformFloatRow::placeSlider(double value)
{
    const QSignalBlocker block(m_slider);
    const double t = (std::clamp(value, m_low, m_high) - m_low) / (m_high - m_low);
    m_slider->setValue(int(std::lround(t * kSliderSteps)));
}

void UniformFloatRow::onFieldChanged(double value)
{
    m_refusal->hide();
    placeSlider(value);
    emit edited(float(value));
}

void UniformFloatRow::onSliderMoved(int position)
{
    const double value = m_low + (m_high - m_low) * double(position) / kSliderSteps;
    m_field->setValue(value); // emits valueChanged -> edited()
}

} // namespace phonglab
