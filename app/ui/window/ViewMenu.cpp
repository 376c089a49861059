#include "ViewMenu.h"

#include "LanguageMenu.h"
#include "MainWindow.h"
#include "ui/check/LiveCheck.h"
#include "ui/performance/PerformanceDock.h"
#include "ui/scene/SceneDock.h"
#include "ui/scene/SceneEditDockSet.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/uniforms/UniformsDock.h"
#include "ui/viewport/Viewport.h"

#include <QAction>
#include <QMenu>
#include <QStatusBar>

namespace phonglab {

namespace {

constexpr int kLanguageMessageMs = 8000;

} // namespace

ViewMenu::ViewMenu(MainWindow *window, QMenu *menu)
    : QObject(window)
{
    Viewport *viewport = window->viewport();
    QAction *resetCamera = menu->addAction(tr("&Reset Camera"), viewport, &Viewport::resetCamera);
    resetCamera->setShortcuts({QKeySequence(Qt::Key_R), QKeySequence(Qt::Key_Home)});
    // Bare-key shortcuts only while the viewport has focus, so typing "r" in
    // any other widget (an editor dock) does not move the camera.
    resetCamera->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    viewport->addAction(resetCamera);

    QAction *resetLayout = menu->addAction(tr("Reset &Layout"), window, &MainWindow::resetLayout);
    resetLayout->setObjectName(QStringLiteral("resetLayout"));
    resetLayout->setToolTip(tr("Put every dock back where a new window has it"));

    QAction *lightMarkers = menu->addAction(tr("Show &Light Markers"));
    lightMarkers->setCheckable(true);
    ViewDrawing &drawing = viewport->drawing();
    lightMarkers->setChecked(drawing.showLightMarkers());
    connect(lightMarkers, &QAction::toggled, viewport,
            [&drawing](bool show) { drawing.setShowLightMarkers(show); });

    menu->addSeparator();
    const auto addDockToggle = [menu](QDockWidget *dock, const QString &text) {
        QAction *toggle = dock->toggleViewAction();
        toggle->setText(text);
        menu->addAction(toggle);
    };
    addDockToggle(window->sceneDock(), tr("&Scene Dock"));
    addDockToggle(window->shaderDock(), tr("S&haders Dock"));
    addDockToggle(window->uniformsDock(), tr("&Uniforms Dock"));
    addDockToggle(window->performanceDock(), tr("&Performance Dock"));
    window->editDocks()->addDockToggles(menu);
    window->liveCheck()->addViewActions(menu);

    menu->addSeparator();
    auto *language = new LanguageMenu(menu->addMenu(tr("L&anguage")), this);
    connect(language, &LanguageMenu::chosen, window, [window](const QString &message) {
        window->statusBar()->showMessage(message, kLanguageMessageMs);
    });
}

} // namespace phonglab
