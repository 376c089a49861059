#include "UniformBoolRow.h"

#include <QBoxLayout>
#include <QCheckBox>
#include <QSignalBlocker>

namespace phonglab {

UniformBoolRow::UniformBoolRow(QWidget *parent)
    : QWidget(parent)
    , m_check(new QCheckBox(this))
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_check);
    layout->addStretch(1);
    connect(m_check, &QCheckBox::toggled, this, &UniformBoolRow::edited);
}

void UniformBoolRow::setValue(bool value)
{
    const QSignalBlocker block(m_check);
    m_check->setChecked(value);
}

bool UniformBoolRow::value() const
{
    return m_check->isChecked();
}

} // namespace phonglab
