#include "DocumentationFiles.h"

#include <algorithm>

#include "core/scene/ResourcePaths.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace phonglab {

namespace {

constexpr int kTitleSearchLines = 20; // a title comes first; no need to read a whole doc

bool holdsDocumentation(const QString &folder)
{
    return !folder.isEmpty() && !documentationFiles(folder).isEmpty();
}

} // namespace

QStringList documentationSearchFolders(const QString &first)
{
    QStringList folders;
    if (!first.isEmpty())
        folders << first;
    if (QCoreApplication::instance())
        folders << QCoreApplication::applicationDirPath()
                + QStringLiteral("/../share/doc/phonglab");
    // The assets on disk (not the embedded copy) tell where the rest of the
    // tree is: assets/ sits in the source tree beside README.md and docs/,
    // and in an install share/phonglab/assets is a sibling of share/doc.
    const QString scene = assetPath(QStringLiteral("scenes/default.json"));
    if (!scene.startsWith(QLatin1Char(':'))) {
        const QString assetParent = QFileInfo(scene).absolutePath() + QStringLiteral("/../..");
        folders << assetParent << assetParent + QStringLiteral("/../doc/phonglab");
    }
    for (QString &folder : folders)
        folder = QDir::cleanPath(folder);
    folders.removeDuplicates();
    return folders;
}

QString documentationFolder(const QString &first)
{
    for (const QString &folder : documentationSearchFolders(first))
        if (holdsDocumentation(folder))
            return folder;
    return {};
}

QStringList documentationFiles(const QString &folder, const QString &language)
{
    const QDir dir(folder);
    QStringList english;
    if (dir.exists(QStringLiteral("README.md")))
        english << dir.filePath(QStringLiteral("README.md"));
    const QDir docs(dir.filePath(QStringLiteral("docs")));
    for (const QString &name : docs.entryList({QStringLiteral("*.md")}, QDir::Files, QDir::Name))
        english << docs.filePath(name);
    // The German pages: their README is their home.
    QStringList german;
    const QDir de(docs.filePath(QStringLiteral("de")));
    for (const QString &name : de.entryList({QStringLiteral("*.md")}, QDir::Files, QDir::Name))
        german << de.filePath(name);
    const auto home = std::find_if(german.begin(), german.end(), [](const QString &p) {
        return QFileInfo(p).fileName() == QLatin1String("README.md");
    });
    if (home != german.end())
        std::rotate(german.begin(), home, home + 1);
    return language == QLatin1String("de") ? german + english : english + german;
}

QString documentTitle(const QString &markdownPath)
{
    QFile file(markdownPath);
    if (file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        for (int line = 0; line < kTitleSearchLines && !file.atEnd(); ++line) {
            const QString text = QString::fromUtf8(file.readLine()).trimmed();
            if (text.startsWith(QLatin1String("# ")))
                return text.mid(2).trimmed();
        }
    }
    return QFileInfo(markdownPath).fileName();
}

} // namespace phonglab
