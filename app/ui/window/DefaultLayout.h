#pragma once
#include <QRect>

class QDockWidget;
class QMainWindow;

namespace phonglab {

// The docks of the main window, by what a user does with them together.
struct WindowDocks {
    // What is in the scene and where: its objects and meshes, one object's
    // placement, the lights.
    QDockWidget *scene = nullptr;
    QDockWidget *object = nullptr;
    QDockWidget *lights = nullptr;
    // The code, and what it is fed: the material, every uniform, and the
    // terms of the equation at one pixel.
    QDockWidget *shaders = nullptr;
    QDockWidget *material = nullptr;
    QDockWidget *uniforms = nullptr;
    QDockWidget *inspector = nullptr;
    // Measuring, on demand.
    QDockWidget *performance = nullptr;
};

// The window's first geometry: this share of the screen's available area,
// centred on it.
inline constexpr double kWindowShareOfScreen = 0.9;
QRect defaultWindowGeometry(const QRect &available);

// The first layout (and View > Reset Layout), for the window's present size.
// The code sits right of the view with room for `editorWidth` (80 columns),
// its error list under it, and under the code the material and the
// uniforms it is fed. Where the window is wide enough, the scene, object
// and light docks are a column of their own left of the view; in a
// narrower window they join the tabs under the code, so that neither the
// view nor the code gets too narrow. Performance and the pixel inspector
// are hidden until asked for (the View menu; Inspect shows the inspector).
void applyDefaultLayout(QMainWindow &window, const WindowDocks &docks, int editorWidth);

// The narrowest view the layout leaves, and the width of the scene column.
inline constexpr int kMinViewportWidth = 420;
inline constexpr int kSceneColumnWidth = 340;

} // namespace phonglab
