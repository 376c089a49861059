#pragma once
#include "SceneCommands.h"

#include <QDockWidget>
#include <functional>

class QUndoCommand;
class QUndoStack;

namespace phonglab {

// The skeleton of every dock that edits the shown scene one item at a time
// (LightsDock: a light; MaterialDock and ObjectDock: an object). It keeps
// the scene it was last shown, a chooser for the item and an editor for the
// chosen one, and turns the editor's changes into commands on the undo
// stack. Subclasses say how many items there are, fill their chooser and
// editor, and build the commands.
class SceneEditDock : public QDockWidget
{
    Q_OBJECT

public:
    void bind(QUndoStack *stack, SceneAccess access);
    // Shows `scene` (after a load or any edit), keeping the chosen item
    // when it still exists.
    void refresh(const Scene &scene);

protected:
    SceneEditDock(const QString &title, const QString &objectName, QWidget *parent);

    const Scene &scene() const { return m_scene; }
    const SceneAccess &access() const { return m_access; }
    // Pushes an edit onto the stack; false (and the command deleted) when
    // the dock is not bound to one.
    bool pushEdit(QUndoCommand *command);
    bool isBound() const { return m_stack != nullptr; }
    // Runs `fill` with the dock's own widget signals not taken as edits.
    void whileShowing(const std::function<void()> &fill);
    bool isShowing() const { return m_showing; }
    // The editor shows the chosen item, or is disabled when there is none.
    void showChosen();

    virtual int chosenIndex() const = 0; // -1: none
    virtual int itemCount() const = 0;   // in scene()
    virtual QWidget *itemEditor() const = 0;
    // From refresh(), while showing: the chooser lists scene()'s items,
    // and anything not about the chosen item is shown.
    virtual void showScene() = 0;
    // The chosen item's values in the editor (never called while showing).
    virtual void showItem(int index) = 0;
    // After every refresh(), once the chosen item is shown.
    virtual void refreshed() { }

private:
    QUndoStack *m_stack = nullptr;
    SceneAccess m_access;
    Scene m_scene;
    bool m_showing = false; // widget signals now are the dock's own, not edits
};

} // namespace phonglab
