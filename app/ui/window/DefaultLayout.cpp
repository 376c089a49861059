#include "DefaultLayout.h"

#include <QDockWidget>
#include <QMainWindow>
#include <algorithm>

namespace phonglab {

namespace {

// The share of the code column's height the editor gets; the tabs under it
// get the rest.
constexpr double kShadersShareOfHeight = 0.6;

void tabify(QMainWindow &window, std::initializer_list<QDockWidget *> docks)
{
    QDockWidget *previous = nullptr;
    for (QDockWidget *dock : docks) {
        if (previous)
            window.tabifyDockWidget(previous, dock);
        previous = dock;
    }
}

} // namespace

QRect defaultWindowGeometry(const QRect &available)
{
    const QSize size(int(available.width() * kWindowShareOfScreen),
                     int(available.height() * kWindowShareOfScreen));
    QRect geometry(QPoint(), size);
    geometry.moveCenter(available.center());
    return geometry;
}

void applyDefaultLayout(QMainWindow &window, const WindowDocks &d, int editorWidth)
{
    const std::initializer_list<QDockWidget *> all = {
        d.scene, d.object, d.lights, d.shaders, d.material, d.uniforms, d.inspector, d.performance};
    for (QDockWidget *dock : all) {
        dock->setFloating(false); // before leaving the layout: a floating one would stay afloat
        window.removeDockWidget(dock);
    }
    // The side columns reach from the toolbar to the status bar.
    window.setCorner(Qt::TopLeftCorner, Qt::LeftDockWidgetArea);
    window.setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    window.setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
    window.setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);

    const int width = window.width();
    const bool sceneColumn = width >= kSceneColumnWidth + editorWidth + kMinViewportWidth;
    const int codeWidth = std::min(editorWidth, std::max(0, width - kMinViewportWidth));

    window.addDockWidget(Qt::RightDockWidgetArea, d.shaders);
    window.addDockWidget(Qt::RightDockWidgetArea, d.material, Qt::Vertical);
    if (sceneColumn) {
        window.addDockWidget(Qt::LeftDockWidgetArea, d.scene);
        tabify(window, {d.scene, d.object, d.lights, d.performance});
        tabify(window, {d.material, d.uniforms, d.inspector});
    } else {
        tabify(window,
               {d.material, d.uniforms, d.lights, d.object, d.scene, d.inspector, d.performance});
    }
    for (QDockWidget *dock : all)
        dock->setVisible(dock != d.performance && dock != d.inspector);
    d.scene->raise();
    d.material->raise();

    window.resizeDocks({d.shaders}, {codeWidth}, Qt::Horizontal);
    if (sceneColumn)
        window.resizeDocks({d.scene}, {kSceneColumnWidth}, Qt::Horizontal);
    const int height = window.centralWidget() ? window.centralWidget()->height() : window.height();
    window.resizeDocks(
        {d.shaders, d.material},
        {int(height * kShadersShareOfHeight), int(height * (1.0 - kShadersShareOfHeight))},
        Qt::Vertical);
}

} // namespace phonglab
