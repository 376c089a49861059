#include "PageServer.h"

#include <QDir>
#include <QFileInfo>
#include <QUrl>

namespace phonglab {

namespace {

// How far a symbolic link may lead: a student's project is untrusted (a
// link in a zip may point anywhere), a teacher's library folder is not
// (Debian's libjs-* packages are links into /usr/share/nodejs).
enum class Links {
    StayInside,
    MayLeave
};

// `relative` inside `folder`, as a canonical path that stays inside it
// (or, for a library, whose name stays inside it).
QString fileInside(const QString &folder, const QString &relative, Links links = Links::StayInside)
{
    if (folder.isEmpty() || relative.isEmpty())
        return {};
    const QString root = QFileInfo(folder).canonicalFilePath();
    if (root.isEmpty())
        return {};
    const QFileInfo file(QDir(root).filePath(relative));
    const QString path = file.canonicalFilePath(); // symbolic links followed
    if (path.isEmpty() || !file.isFile())
        return {};
    const QString named = QDir::cleanPath(file.absoluteFilePath());
    const QString inside = links == Links::StayInside ? path : named;
    if (!inside.startsWith(root + QLatin1Char('/')))
        return {};
    return path;
}

// A library folder answers a path with or without its leading folders:
// the page's "../Common/initShaders.js" is /Common/initShaders.js, found
// in a library folder that holds Common/, or that is Common/ itself.
QString fileInLibrary(const QString &library, const QString &relative)
{
    QStringList parts = relative.split(QLatin1Char('/'), Qt::SkipEmptyParts);
    while (!parts.isEmpty()) {
        if (const QString path = fileInside(library, parts.join(QLatin1Char('/')), Links::MayLeave);
            !path.isEmpty())
            return path;
        parts.removeFirst();
    }
    return {};
}

ServedFile found(const QString &path)
{
    return {path, mimeTypeOfFile(path), {}};
}

ServedFile refused(const QString &why)
{
    return {{}, {}, why};
}

} // namespace

QString mimeTypeOfFile(const QString &fileName)
{
    static const std::pair<const char *, const char *> kTypes[] = {
        {"html", "text/html"},
        {"htm", "text/html"},
        {"js", "text/javascript"},
        {"mjs", "text/javascript"},
        {"css", "text/css"},
        {"json", "application/json"},
        {"png", "image/png"},
        {"jpg", "image/jpeg"},
        {"jpeg", "image/jpeg"},
        {"gif", "image/gif"},
        {"svg", "image/svg+xml"},
        {"webp", "image/webp"},
        {"wasm", "application/wasm"},
        {"glsl", "text/plain"},
        {"vert", "text/plain"},
        {"frag", "text/plain"},
        {"obj", "text/plain"},
        {"mtl", "text/plain"},
        {"txt", "text/plain"},
        {"ply", "application/octet-stream"},
        {"bin", "application/octet-stream"},
    };
    const QString suffix = QFileInfo(fileName).suffix().toLower();
    for (const auto &[ending, type] : kTypes)
        if (suffix == QLatin1String(ending))
            return QString::fromLatin1(type);
    return QStringLiteral("application/octet-stream");
}

ServedFile serveRequest(const PageFolders &folders, const QString &url)
{
    const QUrl parsed(url);
    if (!parsed.isValid())
        return refused(QStringLiteral("not an address"));
    if (parsed.scheme() == QLatin1String("data") || parsed.scheme() == QLatin1String("blob"))
        return refused(QStringLiteral("answered by the browser itself"));
    const QString path = parsed.path(QUrl::FullyDecoded);
    if (url.startsWith(kPageOrigin + QLatin1Char('/'))) {
        const QString relative = path.mid(1);
        if (const QString file = fileInside(folders.project, relative); !file.isEmpty())
            return found(file);
        for (const QString &library : folders.libraries)
            if (const QString file = fileInLibrary(library, relative); !file.isEmpty())
                return found(file);
        return refused(QStringLiteral("not in the project or its library folders"));
    }
    for (const auto &[prefix, local] : folders.urlMap) {
        if (!url.startsWith(prefix))
            continue;
        if (QFileInfo(local).isFile())
            return found(QFileInfo(local).canonicalFilePath());
        const QString rest = QUrl(url.mid(prefix.size())).path(QUrl::FullyDecoded);
        if (const QString file = fileInside(local, rest, Links::MayLeave); !file.isEmpty())
            return found(file);
    }
    // A CDN's copy of a course library the teacher holds: the same file name.
    const QString name = QFileInfo(path).fileName();
    if (parsed.scheme().startsWith(QLatin1String("http")) && !name.isEmpty())
        for (const QString &library : folders.libraries)
            if (const QString file = fileInLibrary(library, name); !file.isEmpty())
                return found(file);
    return refused(QStringLiteral("an outside address: the page gets no network"));
}

} // namespace phonglab
