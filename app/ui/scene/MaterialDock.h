#pragma once
#include "ObjectEditDock.h"

class QComboBox;
class QDoubleSpinBox;
class QSlider;

namespace phonglab {

class Vec3Field;

// The selected object's Phong material: ka, kd, ks (a colour button and three
// numbers each) and the shininess (slider + spin box), plus presets and
// "Save as Preset…". Every change is a SetMaterialCommand on the stack.
class MaterialDock : public ObjectEditDock
{
    Q_OBJECT

public:
    explicit MaterialDock(QWidget *parent = nullptr);

    Vec3Field *field(MaterialField which) const;
    QDoubleSpinBox *shininessBox() const { return m_shininess; }
    QComboBox *presetBox() const { return m_presets; }
    // Applies preset `index` of allMaterialPresets() to the selected object.
    void applyMaterialPreset(int index);
    void saveAsPreset(const QString &name);

protected:
    void showItem(int index) override;

private:
    void buildForm();
    void pushMaterial(const Material &after, MaterialField field);
    void reloadPresets();
    void askPresetName();

    Vec3Field *m_ka = nullptr;
    Vec3Field *m_kd = nullptr;
    Vec3Field *m_ks = nullptr;
    QDoubleSpinBox *m_shininess = nullptr;
    QSlider *m_shininessSlider = nullptr;
    QComboBox *m_presets = nullptr;
};

} // namespace phonglab
