#pragma once
#include "SceneEditDock.h"

class QComboBox;
class QFormLayout;

namespace phonglab {

// A SceneEditDock for one scene object at a time (MaterialDock,
// ObjectDock): an "Object" chooser ("1: tree.obj", ...) heads a form the
// subclass fills with the object's fields.
class ObjectEditDock : public SceneEditDock
{
    Q_OBJECT

public:
    int selectedObject() const;
    void selectObject(int index);

protected:
    ObjectEditDock(const QString &title, const QString &objectName, QWidget *parent);

    QFormLayout *form() const { return m_form; }
    int chosenIndex() const override { return selectedObject(); }
    int itemCount() const override { return int(scene().objects.size()); }
    QWidget *itemEditor() const override;
    void showScene() override;

private:
    QComboBox *m_objects = nullptr;
    QFormLayout *m_form = nullptr;
};

} // namespace phonglab
