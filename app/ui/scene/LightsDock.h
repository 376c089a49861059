#pragma once
#include "SceneEditDock.h"

class QCheckBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QListWidgetItem;
class QPushButton;

namespace phonglab {

class Vec3Field;

// The scene's point lights (at most kMaxLights) in world space: add, remove,
// switch on/off, and for the selected light its name, position, Id, Is and attenuation c1/c2/c3;
// plus the global ambient Ia. Every change is an undoable command.
class LightsDock : public SceneEditDock
{
    Q_OBJECT

public:
    explicit LightsDock(QWidget *parent = nullptr);

    // The selected light (switched on or off); -1 when none.
    int selectedLight() const;
    // The list's check box: switches light `index` on or off (the light stays
    // in the scene either way) through an undoable command; false if nothing changed.
    bool setLightEnabled(int index, bool on);
    // Lights in the scene that are switched off.
    int switchedOffCount() const;
    // The name field: renames light `index` (empty: shown as "Light N"); false if unchanged.
    bool renameLight(int index, const QString &name);
    // What the list shows for light `index`: its name, or "Light N".
    QString displayName(int index) const;
    QLineEdit *nameField() const { return m_name; }
    void selectLight(int index);
    Vec3Field *field(LightField which) const { return m_fields[int(which)]; }
    Vec3Field *ambientField() const { return m_ambient; }
    QCheckBox *headlightBox() const { return m_headlight; }
    void addLight();
    void removeSelectedLight();

signals:
    // The highlighted light changed (-1: none); the viewport marks it.
    void lightSelected(int index);
    // The headlight check box: a view setting, so not an undo step.
    void headlightToggled(bool on);

protected:
    int chosenIndex() const override { return selectedLight(); }
    int itemCount() const override { return int(scene().lights.size()); }
    QWidget *itemEditor() const override { return m_editor; }
    void showScene() override;
    void showItem(int index) override;
    void refreshed() override;

private:
    QWidget *buildList(QWidget *parent);
    Vec3Field *addField(const QString &label, LightField which, double minimum, double maximum);
    void push(LightField which, const glm::dvec3 &after);
    void updateButtons();
    void itemToggled(QListWidgetItem *item);

    QListWidget *m_list = nullptr;
    QLabel *m_status = nullptr;
    QCheckBox *m_headlight = nullptr;
    QPushButton *m_add = nullptr;
    QPushButton *m_remove = nullptr;
    QWidget *m_editor = nullptr;
    QLineEdit *m_name = nullptr;
    Vec3Field *m_fields[4] = {nullptr, nullptr, nullptr, nullptr};
    Vec3Field *m_ambient = nullptr;
};

} // namespace phonglab
