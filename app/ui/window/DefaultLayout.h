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
    // The check's whole verdict, when its short form in the status bar is
    // clicked: a tab beside the material.
    QDockWidget *verdict = nullptr;
};

// The window's first geometry: these shares of the screen's available area,
// centred on it. Taller than wide: on a laptop's 768 lines every line of
// code counts, and the title bar still fits.
inline constexpr double kWindowShareOfScreen = 0.9;
inline constexpr double kWindowShareOfScreenHeight = 0.95;
QRect defaultWindowGeometry(const QRect &available);

// The first layout (and View > Reset Layout), for the window's present size.
// The code sits right of the view with room for `editorWidth` (80 columns,
// where the view keeps half the width beside them: 1600 pixels and up)
// and most of the column's height (its error list under it, shown only when
// there is something to say); under the code, as tabs at the height the
// material needs, the material and the uniforms it is fed. The view keeps
// at least half the width. Where the window is wide enough for that and a
// column more, the scene, object and light docks are a column of their own
// left of the view; otherwise they join the tabs under the code. Performance, the pixel inspector and
// the check's verdict are hidden until asked for (the View menu; Inspect shows
// the inspector, a click on the status bar's verdict the verdict).
void applyDefaultLayout(QMainWindow &window, const WindowDocks &docks, int editorWidth);

// A dock in the tabs under the code, just brought to the front for what it
// shows (Inspect's pixel, the verdict, a uniform to place): the tabs grow to
// its contents' height, up to half the column, so that it is read rather
// than scrolled; the code gives the room. A dock elsewhere, or tall enough
// already, is left as it is.
inline constexpr double kMostRoomForAShownDock = 0.5;
void giveRoomUnderTheCode(QMainWindow &window, const WindowDocks &docks, QDockWidget *dock);

// Puts a dock's contents in a frameless scroll area: a dock in the tabs
// under the code must not make them taller than the tab shown needs (the
// lights' editor alone asks for ~350 pixels), so that the code keeps its
// height; a dock made short scrolls.
void scrollWhenShort(QDockWidget *dock);

// The narrowest view the layout leaves, and the width of the scene column.
inline constexpr int kMinViewportWidth = 420;
inline constexpr int kSceneColumnWidth = 340;

} // namespace phonglab
