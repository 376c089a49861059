#pragma once
#include <QWidget>

class QCheckBox;

namespace phonglab {

// A bool uniform: a check box.
class UniformBoolRow : public QWidget
{
    Q_OBJECT

public:
    explicit UniformBoolRow(QWidget *parent = nullptr);

    void setValue(bool value); // no edited()
    bool value() const;
    QCheckBox *checkBox() const { return m_check; }

signals:
    void edited(bool value);

private:
    QCheckBox *m_check = nullptr;
};

} // namespace phonglab
