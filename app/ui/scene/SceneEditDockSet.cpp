#include "SceneEditDockSet.h"

#include "LightsDock.h"
#include "MaterialDock.h"
#include "ObjectDock.h"
#include "ui/viewport/Viewport.h"

#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QUndoStack>

namespace phonglab {

SceneEditDockSet::SceneEditDockSet(QMainWindow *window, Viewport *viewport)
    : QObject(window)
    , m_viewport(viewport)
    , m_stack(new QUndoStack(this))
    , m_lights(new LightsDock(window))
    , m_material(new MaterialDock(window))
    , m_object(new ObjectDock(window))
{
    for (QDockWidget *dock :
         {static_cast<QDockWidget *>(m_lights), static_cast<QDockWidget *>(m_material),
          static_cast<QDockWidget *>(m_object)})
        window->addDockWidget(Qt::RightDockWidgetArea, dock); // DefaultLayout places them

    m_lights->bind(m_stack, access());
    m_material->bind(m_stack, access());
    m_object->bind(m_stack, access());
    connect(m_viewport, &Viewport::sceneChanged, this, &SceneEditDockSet::sceneReplaced);
    connect(m_viewport, &Viewport::sceneParametersChanged, this, &SceneEditDockSet::refresh);
    connect(m_viewport, &Viewport::lightDragged, this, &SceneEditDockSet::pushDrag);
    connect(m_viewport, &Viewport::lightPicked, m_lights, &LightsDock::selectLight);
    ViewDrawing &drawing = m_viewport->drawing();
    connect(m_lights, &LightsDock::lightSelected, m_viewport,
            [&drawing](int index) { drawing.setSelectedLight(index); });
    connect(m_lights, &LightsDock::headlightToggled, m_viewport,
            [&drawing](bool on) { drawing.setHeadlight(on); });
    refresh();
}

SceneAccess SceneEditDockSet::access() const
{
    Viewport *viewport = m_viewport;
    return {[viewport] { return viewport->currentScene(); },
            [viewport](const Scene &scene) { viewport->setSceneParameters(scene); }};
}

void SceneEditDockSet::addEditActions(QMenu *edit)
{
    QAction *undo = m_stack->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence(tr("Ctrl+Z")));
    QAction *redo = m_stack->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence(tr("Ctrl+Shift+Z")));
    edit->addAction(undo);
    edit->addAction(redo);
}

void SceneEditDockSet::addDockToggles(QMenu *view)
{
    view->addAction(m_lights->toggleViewAction());
    view->addAction(m_material->toggleViewAction());
    view->addAction(m_object->toggleViewAction());
}

void SceneEditDockSet::refresh()
{
    const Scene scene = m_viewport->currentScene();
    m_lights->refresh(scene);
    m_material->refresh(scene);
    m_object->refresh(scene);
}

void SceneEditDockSet::sceneReplaced()
{
    // Also when only a mesh's normals were reloaded: commands hold light and
    // object indices, and a reloaded scene may no longer have them.
    m_stack->clear();
    refresh();
}

void SceneEditDockSet::pushDrag(int index, const PointLight &before, const PointLight &after)
{
    // The viewport has already moved the light; redo() on push writes the same.
    m_stack->push(new SetLightCommand(access(), index, before, after, LightField::Position, false));
}

} // namespace phonglab
