#include "ShortcutsDialog.h"

#include "ui/viewport/Viewport.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QHeaderView>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSet>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace phonglab {

namespace {

const QString kPathSeparator = QStringLiteral(" › ");
const QSize kDefaultSize(640, 480);

// "Save Scene &As…" → "Save Scene As…"
QString plainText(QString text)
{
    static const QRegularExpression mnemonic(QStringLiteral("&(?!&)"));
    return text.remove(mnemonic).replace(QLatin1String("&&"), QLatin1String("&"));
}

QString keysText(const QAction *action)
{
    QStringList keys;
    for (const QKeySequence &key : action->shortcuts())
        keys << key.toString(QKeySequence::NativeText);
    return keys.join(QLatin1String(", "));
}

// The part of the window a widget is in, as a user would name it.
QString areaName(const QWidget *widget)
{
    for (const QWidget *w = widget; w && !w->isWindow(); w = w->parentWidget()) {
        if (qobject_cast<const Viewport *>(w))
            return ShortcutsDialog::tr("3D view");
        if (const auto *dock = qobject_cast<const QDockWidget *>(w))
            return ShortcutsDialog::tr("%1 dock").arg(dock->windowTitle());
    }
    return ShortcutsDialog::tr("window");
}

QList<QWidget *> widgetsOf(const QAction *action, const QMainWindow &window)
{
    QList<QWidget *> widgets;
    for (QObject *object : action->associatedObjects())
        if (auto *widget = qobject_cast<QWidget *>(object); widget && widget->window() == &window)
            widgets << widget;
    return widgets;
}

// Where a key works follows its shortcut context: the whole window, or only
// while the focus is in one of the widgets that carry the action.
QString scopeOf(const QAction *action, const QMainWindow &window)
{
    switch (action->shortcutContext()) {
    case Qt::ApplicationShortcut: return ShortcutsDialog::tr("anywhere in PhongLab");
    case Qt::WindowShortcut: return ShortcutsDialog::tr("anywhere in the window");
    case Qt::WidgetShortcut:
    case Qt::WidgetWithChildrenShortcut: break;
    }
    QStringList areas;
    for (const QWidget *widget : widgetsOf(action, window))
        if (!qobject_cast<const QMenu *>(widget) && !qobject_cast<const QToolBar *>(widget)
            && !qobject_cast<const QToolButton *>(widget) && !areas.contains(areaName(widget)))
            areas << areaName(widget);
    if (areas.isEmpty())
        areas << ShortcutsDialog::tr("toolbar");
    return ShortcutsDialog::tr("while the %1 has the focus")
        .arg(areas.join(ShortcutsDialog::tr(" or the ")));
}

// Where the action shows outside the menus: a named toolbar, else its area.
QString placeOf(const QAction *action, const QMainWindow &window)
{
    const QList<QWidget *> widgets = widgetsOf(action, window);
    for (const QWidget *widget : widgets)
        if (const auto *bar = qobject_cast<const QToolBar *>(widget);
            bar && !bar->windowTitle().isEmpty())
            return ShortcutsDialog::tr("%1 toolbar").arg(bar->windowTitle());
    if (widgets.isEmpty())
        return ShortcutsDialog::tr("Window");
    QString area = areaName(widgets.front());
    area[0] = area[0].toUpper();
    return area;
}

// What collect() has gathered so far: each action is listed once, where it
// is first met.
struct Collected {
    const QMainWindow &window;
    QSet<const QAction *> seen;
    QList<ShortcutsDialog::Entry> entries;

    void add(QAction *action, const QString &command)
    {
        seen.insert(action);
        if (!action->shortcuts().isEmpty())
            entries.append({action, command, keysText(action), scopeOf(action, window)});
    }
};

void addMenu(Collected &collected, const QMenu *menu, const QStringList &path)
{
    for (QAction *action : menu->actions()) {
        if (action->isSeparator() || collected.seen.contains(action))
            continue;
        const QStringList here = path + QStringList{plainText(action->text())};
        if (const QMenu *sub = action->menu()) {
            collected.seen.insert(action);
            addMenu(collected, sub, here);
        } else {
            collected.add(action, here.join(kPathSeparator));
        }
    }
}

// Actions on toolbars, docks and the window itself, after the menus.
void addWidgetActions(Collected &collected)
{
    QList<const QWidget *> widgets{&collected.window};
    for (const QWidget *child : collected.window.findChildren<QWidget *>())
        if (child->window() == &collected.window)
            widgets << child;
    for (const QWidget *widget : widgets)
        for (QAction *action : widget->actions())
            if (!collected.seen.contains(action) && !action->menu())
                collected.add(action,
                              placeOf(action, collected.window) + kPathSeparator
                                  + plainText(action->text()));
}

} // namespace

QList<ShortcutsDialog::Entry> ShortcutsDialog::collect(const QMainWindow &window)
{
    Collected collected{window, {}, {}};
    if (const QMenuBar *bar = window.menuBar())
        for (const QAction *action : bar->actions())
            if (const QMenu *menu = action->menu())
                addMenu(collected, menu, {plainText(action->text())});
    addWidgetActions(collected);
    return collected.entries;
}

ShortcutsDialog::ShortcutsDialog(QMainWindow *window)
    : QDialog(window)
    , m_window(window)
    , m_table(new QTreeWidget(this))
{
    setWindowTitle(tr("Keyboard Shortcuts — PhongLab"));
    m_table->setColumnCount(3);
    m_table->setHeaderLabels({tr("Command"), tr("Shortcut"), tr("Works")});
    m_table->setRootIsDecorated(false);
    m_table->setAlternatingRowColors(true);
    m_table->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(buttons);
    resize(kDefaultSize);
    refresh();
}

void ShortcutsDialog::refresh()
{
    m_entries = collect(*m_window);
    m_table->clear();
    for (const Entry &entry : m_entries)
        new QTreeWidgetItem(m_table, {entry.command, entry.keys, entry.scope});
}

} // namespace phonglab
