#include "UniformIntRow.h"

#include <QBoxLayout>
#include <QSignalBlocker>
#include <QSpinBox>

namespace phonglab {

UniformIntRow::UniformIntRow(int low, int high, QWidget *parent)
    : QWidget(parent)
    , m_spin(new QSpinBox(this))
{
    m_spin->setRange(low, high);
    m_spin->setKeyboardTracking(false);
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_spin);
    layout->addStretch(1);
    connect(m_spin, &QSpinBox::valueChanged, this, &UniformIntRow::edited);
}

void UniformIntRow::setValue(int value)
{
    const QSignalBlocker block(m_spin);
    m_spin->setValue(value);
}

int UniformIntRow::value() const
{
    return m_spin->value();
}

} // namespace phonglab
