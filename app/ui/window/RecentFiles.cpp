#include "RecentFiles.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace phonglab {

namespace {
const QString kSettingsKey = QStringLiteral("recentFiles");
} // namespace

RecentFiles::RecentFiles(QMenu *menu, QObject *parent)
    : QObject(parent)
    , m_menu(menu)
{
    // Filled on demand, so the list is never stale: another PhongLab window
    // may have added to the settings meanwhile.
    connect(m_menu, &QMenu::aboutToShow, this, &RecentFiles::fillMenu);
    fillMenu(); // the shortcuts and the enabled state are right from the start
}

QStringList RecentFiles::files() const
{
    return QSettings().value(kSettingsKey).toStringList();
}

void RecentFiles::add(const QString &path)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList list = files();
    list.removeAll(absolute);
    list.prepend(absolute);
    store(list.mid(0, kMaxFiles));
}

void RecentFiles::remove(const QString &path)
{
    QStringList list = files();
    list.removeAll(path);
    store(list);
}

void RecentFiles::clear()
{
    store({});
}

void RecentFiles::store(const QStringList &list)
{
    QSettings().setValue(kSettingsKey, list);
    fillMenu();
}

void RecentFiles::fillMenu()
{
    m_menu->clear();
    const QStringList list = files();
    for (int i = 0; i < list.size(); ++i) {
        const QString &path = list[i];
        // &1 … &9, then &0: keyboard access to every entry.
        const QString text = tr("&%1 %2").arg((i + 1) % 10).arg(QFileInfo(path).fileName());
        QAction *action = m_menu->addAction(text);
        // Queued: choosing rebuilds this menu, which deletes the action.
        connect(
            action, &QAction::triggered, this, [this, path] { choose(path); },
            Qt::QueuedConnection);
        action->setToolTip(QDir::toNativeSeparators(path));
        action->setStatusTip(QDir::toNativeSeparators(path));
    }
    if (!list.isEmpty())
        m_menu->addSeparator();
    QAction *clearAction = m_menu->addAction(tr("&Clear Recent"));
    connect(clearAction, &QAction::triggered, this, &RecentFiles::clear, Qt::QueuedConnection);
    clearAction->setEnabled(!list.isEmpty());
    m_menu->setToolTipsVisible(true);
}

void RecentFiles::choose(const QString &path)
{
    if (QFileInfo::exists(path)) {
        emit fileChosen(path);
        return;
    }
    remove(path);
    emit missingFileChosen(path);
}

} // namespace phonglab
