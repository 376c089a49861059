#pragma once
#include <QWidget>

class QLabel;
class QSlider;

namespace phonglab {

class UniformNumberField;

// A float uniform: a slider over [low, high] and a number field beside it.
// The field takes only finite numbers inside the field's range (see
// UniformNumberField); a refused input is named in a red line below.
class UniformFloatRow : public QWidget
{
    Q_OBJECT

public:
    // fieldLow/fieldHigh bound what may be typed; sliderLow/sliderHigh what
    // the slider spans (the same for an @range, wider for the field without).
    UniformFloatRow(double sliderLow, double sliderHigh, double fieldLow, double fieldHigh,
                    double step, QWidget *parent = nullptr);

    void setValue(float value); // no edited()
    float value() const;
    UniformNumberField *field() const { return m_field; }
    QSlider *slider() const { return m_slider; }
    QLabel *refusalLabel() const { return m_refusal; }

signals:
    void edited(float value);

private:
    void onFieldChanged(double value);
    void onSliderMoved(int position);
    void placeSlider(double value);

    static constexpr int kSliderSteps = 1000;
    double m_low = 0.0;
    double m_high = 1.0;
    UniformNumberField *m_field = nullptr;
    QSlider *m_slider = nullptr;
    QLabel *m_refusal = nullptr;
};

} // namespace phonglab
