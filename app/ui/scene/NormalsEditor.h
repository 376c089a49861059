#pragma once
#include "core/scene/NormalOptions.h"

#include <QGroupBox>

class QCheckBox;
class QComboBox;
class QSpinBox;

namespace phonglab {

// How one object's mesh gets its normals: a method (auto, flat, average,
// area, angle) and an optional crease angle. Reports every edit the user
// makes; setOptions() does not.
class NormalsEditor : public QGroupBox
{
    Q_OBJECT

public:
    explicit NormalsEditor(QWidget *parent = nullptr);

    void setOptions(const NormalOptions &options);
    NormalOptions options() const;
    // Off for builtin shapes, which have exact analytic normals, and when no
    // object is selected; `reason` becomes the tooltip.
    void setApplicable(bool applicable, const QString &reason = {});

signals:
    void optionsEdited(const phonglab::NormalOptions &options);

private:
    void emitEdited();
    void updateCreaseEnabled();

    QComboBox *m_method = nullptr;
    QCheckBox *m_creaseEnabled = nullptr;
    QSpinBox *m_creaseAngle = nullptr;
};

} // namespace phonglab
