#pragma once
#include "SceneCommands.h"

#include <QDockWidget>

class QComboBox;
class QDoubleSpinBox;
class QSlider;
class QUndoStack;

namespace phonglab {

class Vec3Field;

// The selected object's Phong material: ka, kd, ks (a colour button and three
// numbers each) and the shininess (slider + spin box), plus presets and
// "Save as Preset…". Every change is a SetMaterialCommand on the stack.
class MaterialPanel : public QDockWidget
{
    Q_OBJECT

public:
    explicit MaterialPanel(QWidget *parent = nullptr);

    void bind(QUndoStack *stack, SceneAccess access);
    // Shows `scene` (after a load or any edit); keeps the selected object.
    void refresh(const Scene &scene);

    int selectedObject() const;
    void selectObject(int index);
    Vec3Field *field(MaterialField which) const;
    QDoubleSpinBox *shininessBox() const { return m_shininess; }
    QComboBox *presetBox() const { return m_presets; }
    // Applies preset `index` of allMaterialPresets() to the selected object.
    void applyPreset(int index);
    void saveAsPreset(const QString &name);

private:
    QWidget *buildForm();
    void showSelected();
    void pushMaterial(const Material &after, MaterialField field);
    void reloadPresets();
    void askPresetName();

    QUndoStack *m_stack = nullptr;
    SceneAccess m_access;
    Scene m_scene;
    QComboBox *m_objects = nullptr;
    Vec3Field *m_ka = nullptr;
    Vec3Field *m_kd = nullptr;
    Vec3Field *m_ks = nullptr;
    QDoubleSpinBox *m_shininess = nullptr;
    QSlider *m_shininessSlider = nullptr;
    QComboBox *m_presets = nullptr;
    bool m_showing = false; // refresh in progress: widget signals are not edits
};

} // namespace phonglab
