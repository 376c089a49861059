#pragma once
#include <QObject>
#include <QStringList>

class QMenu;

namespace phonglab {

// File → Examples: one entry per shipped scene, each with its thumbnail
// (assets/scenes/thumbnails/<name>.png, made by scripts/make-thumbnails.sh).
// The scenes are whatever the scenes folder holds at run time (assetPath():
// on disk, else the copy embedded in the binary), so a scene added there
// shows up without a code change.
class ExamplesMenu : public QObject
{
    Q_OBJECT

public:
    ExamplesMenu(QMenu *menu, QObject *parent = nullptr);

    // The shipped scene files, by name.
    static QStringList sceneFiles();
    // "grazing.json" → "Grazing Light" (known scenes), else the name capitalised.
    static QString title(const QString &sceneFile);
    // The thumbnail of a scene file; empty when the scene has none.
    static QString thumbnailPath(const QString &sceneFile);

signals:
    // An example was chosen: open it as File → Open does.
    void sceneChosen(const QString &path);
};

} // namespace phonglab
