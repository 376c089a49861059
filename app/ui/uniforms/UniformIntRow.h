#pragma once
#include <QWidget>

class QSpinBox;

namespace phonglab {

// An int or uint uniform: a spin box (QSpinBox itself refuses non-integers
// and values outside its range).
class UniformIntRow : public QWidget
{
    Q_OBJECT

public:
    UniformIntRow(int low, int high, QWidget *parent = nullptr);

    void setValue(int value); // no edited()
    int value() const;
    QSpinBox *spinBox() const { return m_spin; }

signals:
    void edited(int value);

private:
    QSpinBox *m_spin = nullptr;
};

} // namespace phonglab
