#pragma once
#include <QList>
#include <QWidget>

class QLabel;
class QToolButton;

namespace phonglab {

class UniformNumberField;

// A vec2/3/4 uniform: one number field per component, and for colours
// (vec3 named like one, or annotated @color) a swatch button that opens a
// colour dialog. Refused input is named in a red line below.
class UniformVectorRow : public QWidget
{
    Q_OBJECT

public:
    UniformVectorRow(int components, bool color, double low, double high, double step,
                     QWidget *parent = nullptr);

    void setValues(const QList<float> &values); // no edited()
    QList<float> values() const;
    UniformNumberField *field(int component) const { return m_fields.value(component); }
    QToolButton *colorButton() const { return m_colorButton; }
    QLabel *refusalLabel() const { return m_refusal; }

signals:
    void edited(const QList<float> &values);

private:
    void addColorButton(QLayout *line);
    void chooseColor();
    void updateSwatch();
    void onFieldChanged();

    QList<UniformNumberField *> m_fields;
    QToolButton *m_colorButton = nullptr;
    QLabel *m_refusal = nullptr;
};

} // namespace phonglab
