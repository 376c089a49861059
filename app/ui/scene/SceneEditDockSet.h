#pragma once
#include "SceneCommands.h"

#include <QObject>

class QMainWindow;
class QMenu;
class QUndoStack;

namespace phonglab {

class LightsDock;
class MaterialDock;
class ObjectDock;
class Viewport;

// The docks that edit the shown scene in place (lights, material, object
// placement) and the undo stack their edits go on. Edits reach the viewport
// through its cheap parameter path (Viewport::setSceneParameters), so no
// mesh is reloaded; a new scene clears the stack, since its commands name
// lights and objects of the old one.
class SceneEditDockSet : public QObject
{
    Q_OBJECT

public:
    // The docks go into `window`; MainWindow lays them out (DefaultLayout).
    SceneEditDockSet(QMainWindow *window, Viewport *viewport);

    // Undo / Redo (Ctrl+Z, Ctrl+Shift+Z) into `edit`; the docks' toggles into `view`.
    void addEditActions(QMenu *edit);
    void addDockToggles(QMenu *view);

    QUndoStack *undoStack() const { return m_stack; }
    LightsDock *lightsDock() const { return m_lights; }
    MaterialDock *materialDock() const { return m_material; }
    ObjectDock *objectDock() const { return m_object; }
    SceneAccess access() const;

private:
    void refresh();
    void sceneReplaced();
    void pushDrag(int index, const PointLight &before, const PointLight &after);

    Viewport *m_viewport = nullptr;
    QUndoStack *m_stack = nullptr;
    LightsDock *m_lights = nullptr;
    MaterialDock *m_material = nullptr;
    ObjectDock *m_object = nullptr;
};

} // namespace phonglab
