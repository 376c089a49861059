#pragma once
#include <QDialog>
#include <QList>
#include <QPointer>

class QAction;
class QMainWindow;
class QMenu;
class QTreeWidget;

namespace phonglab {

// Help → Keyboard Shortcuts: every key of the window, read from its actions
// each time the list is filled, so it cannot drift from what the keys do.
// The menus come first, in menu order ("File › Open Scene…"), then the
// actions that live on a toolbar or a dock (Inspect, Compile). The keys of
// the 3D view are actions too (Viewport::keyPressEvent triggers the view's
// actions), so they are listed with where they work.
class ShortcutsDialog : public QDialog
{
    Q_OBJECT

public:
    struct Entry {
        QPointer<QAction> action;
        QString command; // menu path or place, and the action's text
        QString keys;    // every shortcut, in the platform's own notation
        QString scope;   // where the keys work
    };

    explicit ShortcutsDialog(QMainWindow *window);

    // Every action of `window` (menus, toolbars, docks, the window itself)
    // that has a shortcut; another top-level window's actions are not its.
    static QList<Entry> collect(const QMainWindow &window);
    // Reads the actions again.
    void refresh();
    QList<Entry> entries() const { return m_entries; }
    QTreeWidget *table() const { return m_table; }

private:
    QMainWindow *m_window = nullptr;
    QList<Entry> m_entries;
    QTreeWidget *m_table = nullptr;
};

} // namespace phonglab
