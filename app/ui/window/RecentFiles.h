#pragma once
#include <QObject>
#include <QStringList>

class QMenu;

namespace phonglab {

// File → Recent: the last scenes and meshes opened (newest first), kept in
// QSettings so they survive restarts. Fills the menu it is given each time it
// is about to show.
class RecentFiles : public QObject
{
    Q_OBJECT

public:
    static constexpr int kMaxFiles = 10;

    explicit RecentFiles(QMenu *menu, QObject *parent = nullptr);

    QStringList files() const;
    void add(const QString &path); // moves it to the top when already listed
    void remove(const QString &path);
    void clear();

signals:
    // A listed file was chosen that still exists.
    void fileChosen(const QString &path);
    // A listed file was chosen that is gone; it has been removed from the list.
    void missingFileChosen(const QString &path);

private:
    void fillMenu();
    void choose(const QString &path);
    void store(const QStringList &files);

    QMenu *m_menu = nullptr;
};

} // namespace phonglab
