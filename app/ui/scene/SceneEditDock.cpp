#include "SceneEditDock.h"

#include <QUndoStack>

namespace phonglab {

SceneEditDock::SceneEditDock(const QString &title, const QString &objectName, QWidget *parent)
    : QDockWidget(title, parent)
{
    setObjectName(objectName);
}

void SceneEditDock::bind(QUndoStack *stack, SceneAccess access)
{
    m_stack = stack;
    m_access = std::move(access);
}

void SceneEditDock::refresh(const Scene &scene)
{
    m_scene = scene;
    whileShowing([this] { showScene(); });
    showChosen();
    refreshed();
}

bool SceneEditDock::pushEdit(QUndoCommand *command)
{
    if (!m_stack) {
        delete command;
        return false;
    }
    m_stack->push(command);
    return true;
}

void SceneEditDock::whileShowing(const std::function<void()> &fill)
{
    const bool wasShowing = std::exchange(m_showing, true);
    fill();
    m_showing = wasShowing;
}

void SceneEditDock::showChosen()
{
    const int index = chosenIndex();
    const bool valid = index >= 0 && index < itemCount();
    itemEditor()->setEnabled(valid);
    if (!valid || m_showing)
        return;
    whileShowing([&] { showItem(index); });
}

} // namespace phonglab
