#pragma once
#include <QObject>

class QMenu;

namespace phonglab {

class MainWindow;

// The View menu: the camera back home (R, Home: while the view has focus),
// the docks back where a new window has them, the light markers, one toggle
// per dock and the language (LanguageMenu).
class ViewMenu : public QObject
{
    Q_OBJECT

public:
    ViewMenu(MainWindow *window, QMenu *menu);
};

} // namespace phonglab
