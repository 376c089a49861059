#pragma once
#include <QWidget>
#include <functional>
#include <glm/glm.hpp>

class QLabel;
class QLineEdit;
class QPushButton;

namespace phonglab {

// Three numbers edited as one value (a position, a colour, c1/c2/c3). Text
// is checked when an edit is finished: NaN, infinity, a value outside
// [minimum, maximum] or one the extra check refuses (a zero scale, a
// non-positive attenuation sum) is refused with the reason shown under the
// field, and the last valid value comes back. Only accepted values are
// reported, through edited().
class Vec3Field : public QWidget
{
    Q_OBJECT

public:
    // Returns an empty string when the value is acceptable, else why not.
    using Check = std::function<QString(const glm::dvec3 &)>;

    Vec3Field(double minimum, double maximum, QWidget *parent = nullptr);

    void setCheck(Check check) { m_check = std::move(check); }
    // Adds a button that picks the value as an RGB colour in [0, 1].
    void enableColourPicker();
    void setValue(const glm::dvec3 &value); // shown as is; emits nothing
    glm::dvec3 value() const { return m_value; }

    // What a person types, for tests: text into one component, then commit.
    QLineEdit *component(int axis) const { return m_edits[axis]; }
    bool commit();
    QString errorText() const;

signals:
    void edited(const glm::dvec3 &before, const glm::dvec3 &after);

private:
    QString parse(glm::dvec3 *parsed) const;
    void refuse(const QString &reason);
    void pickColour();
    void showValue();

    QLineEdit *m_edits[3] = {nullptr, nullptr, nullptr};
    QLabel *m_error = nullptr;
    QPushButton *m_colour = nullptr;
    double m_minimum = 0.0;
    double m_maximum = 0.0;
    Check m_check;
    glm::dvec3 m_value{0.0};
};

} // namespace phonglab
