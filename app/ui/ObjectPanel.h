#pragma once
#include "SceneCommands.h"

#include <QDockWidget>

class QComboBox;
class QUndoStack;

namespace phonglab {

class Vec3Field;

// Places the selected object: translate, rotate (degrees, about X then Y then
// Z) and scale per axis. Non-uniform scale is fine; a zero scale (the object
// would collapse and its normals with it) is refused at the field.
class ObjectPanel : public QDockWidget
{
    Q_OBJECT

public:
    explicit ObjectPanel(QWidget *parent = nullptr);

    void bind(QUndoStack *stack, SceneAccess access);
    void refresh(const Scene &scene);

    int selectedObject() const;
    void selectObject(int index);
    Vec3Field *field(TransformField which) const;

private:
    Vec3Field *addField(const QString &label, TransformField which, double limit);
    void showSelected();
    void push(TransformField which, const glm::dvec3 &after);

    QUndoStack *m_stack = nullptr;
    SceneAccess m_access;
    Scene m_scene;
    QComboBox *m_objects = nullptr;
    Vec3Field *m_fields[3] = {nullptr, nullptr, nullptr};
    bool m_showing = false;
};

} // namespace phonglab
