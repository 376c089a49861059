#include "UniformVectorRow.h"

#include "UniformNumberField.h"

#include <QBoxLayout>
#include <QColorDialog>
#include <QLabel>
#include <QPixmap>
#include <QSignalBlocker>
#include <QToolButton>
#include <algorithm>

namespace phonglab {

UniformVectorRow::UniformVectorRow(int components, bool color, double low, double high, double step,
                                   QWidget *parent)
    : QWidget(parent)
    , m_refusal(new QLabel(this))
{
    auto *line = new QHBoxLayout;
    line->setContentsMargins(0, 0, 0, 0);
    if (color)
        addColorButton(line);
    for (int i = 0; i < components; ++i) {
        auto *field = new UniformNumberField(this);
        field->setRange(low, high);
        field->setSingleStep(step);
        line->addWidget(field);
        connect(field, &QDoubleSpinBox::valueChanged, this, &UniformVectorRow::onFieldChanged);
        connect(field, &UniformNumberField::refused, this, [this](const QString &reason) {
            m_refusal->setText(tr("Refused: %1").arg(reason));
            m_refusal->show();
        });
        m_fields.append(field);
    }
    m_refusal->setStyleSheet(QStringLiteral("color: #d32f2f;"));
    m_refusal->setWordWrap(true);
    m_refusal->hide();
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(line);
    layout->addWidget(m_refusal);
}

void UniformVectorRow::addColorButton(QLayout *line)
{
    m_colorButton = new QToolButton(this);
    m_colorButton->setToolTip(tr("Choose a colour"));
    line->addWidget(m_colorButton);
    connect(m_colorButton, &QToolButton::clicked, this, &UniformVectorRow::chooseColor);
}

void UniformVectorRow::setValues(const QList<float> &values)
{
    for (int i = 0; i < m_fields.size() && i < values.size(); ++i) {
        const QSignalBlocker block(m_fields[i]);
        m_fields[i]->setValue(values[i]);
    }
    updateSwatch();
}

QList<float> UniformVectorRow::values() const
{
    QList<float> list;
    for (const UniformNumberField *field : m_fields)
        list.append(float(field->value()));
    return list;
}

void UniformVectorRow::updateSwatch()
{
    if (!m_colorButton || m_fields.size() < 3)
        return;
    // Intensities above 1 show as the colour they clamp to on screen.
    auto channel = [this](int i) { return std::clamp(m_fields[i]->value(), 0.0, 1.0); };
    QPixmap swatch(16, 16);
    swatch.fill(QColor::fromRgbF(float(channel(0)), float(channel(1)), float(channel(2))));
    m_colorButton->setIcon(QIcon(swatch));
}

void UniformVectorRow::chooseColor()
{
    const QList<float> now = values();
    const QColor initial =
        QColor::fromRgbF(std::clamp(now[0], 0.0f, 1.0f), std::clamp(now[1], 0.0f, 1.0f),
                         std::clamp(now[2], 0.0f, 1.0f));
    const QColor chosen = QColorDialog::getColor(initial, this, tr("Choose a colour"));
    if (!chosen.isValid())
        return;
    setValues({float(chosen.redF()), float(chosen.greenF()), float(chosen.blueF())});
    emit edited(values());
}

void UniformVectorRow::onFieldChanged()
{
    m_refusal->hide();
    updateSwatch();
    emit edited(values());
}

} // namespace phonglab
