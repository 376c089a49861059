#include "ExamplesMenu.h"

#include "ThumbnailMenuStyle.h"
#include "core/scene/ResourcePaths.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QIcon>
#include <QMenu>

#include <algorithm>

namespace phonglab {

namespace {

// Titles for the scenes shipped today; a scene not named here still shows,
// under its file name.
struct KnownScene {
    const char *name;
    const char *title;
};
constexpr KnownScene kKnownScenes[] = {
    {"default", QT_TRANSLATE_NOOP("phonglab::ExamplesMenu", "Tree and Cloud (the default)")},
    {"check", QT_TRANSLATE_NOOP("phonglab::ExamplesMenu", "Two Spheres (the check scene)")},
    {"grazing", QT_TRANSLATE_NOOP("phonglab::ExamplesMenu", "Grazing Light on a Box")},
    {"sphere", QT_TRANSLATE_NOOP("phonglab::ExamplesMenu", "Sphere")},
    {"torus", QT_TRANSLATE_NOOP("phonglab::ExamplesMenu", "Torus")},
};

// The default scene is always shipped, on disk or embedded: its folder is the
// scenes folder.
QString scenesFolder()
{
    return QFileInfo(defaultScenePath()).path();
}

} // namespace

ExamplesMenu::ExamplesMenu(QMenu *menu, QObject *parent)
    : QObject(parent)
{
    for (const QString &file : sceneFiles()) {
        const QString thumbnail = thumbnailPath(file);
        QAction *action =
            menu->addAction(thumbnail.isEmpty() ? QIcon() : QIcon(thumbnail), title(file));
        action->setToolTip(QDir::toNativeSeparators(file));
        action->setData(file);
        connect(action, &QAction::triggered, this, [this, file] { emit sceneChosen(file); });
    }
    menu->setEnabled(!menu->isEmpty());
    menu->setStyle(new ThumbnailMenuStyle(menu)); // thumbnails big enough to tell apart
}

QStringList ExamplesMenu::sceneFiles()
{
    const QDir folder(scenesFolder());
    QStringList files;
    for (const QString &name :
         folder.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        files << folder.filePath(name);
    // The default scene first: it is where a new user starts.
    const auto isDefault = [](const QString &f) {
        return QFileInfo(f).fileName() == QLatin1String("default.json");
    };
    std::stable_partition(files.begin(), files.end(), isDefault);
    return files;
}

QString ExamplesMenu::title(const QString &sceneFile)
{
    const QString name = QFileInfo(sceneFile).completeBaseName();
    for (const KnownScene &known : kKnownScenes)
        if (name == QLatin1String(known.name))
            return tr(known.title);
    QString readable = name;
    readable.replace(QLatin1Char('-'), QLatin1Char(' '))
        .replace(QLatin1Char('_'), QLatin1Char(' '));
    if (!readable.isEmpty())
        readable[0] = readable[0].toUpper();
    return readable;
}

QString ExamplesMenu::thumbnailPath(const QString &sceneFile)
{
    const QString path = assetPath(
        QStringLiteral("scenes/thumbnails/%1.png").arg(QFileInfo(sceneFile).completeBaseName()));
    return QFileInfo::exists(path) ? path : QString();
}

} // namespace phonglab
