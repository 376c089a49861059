#pragma once
#include <QString>
#include <QStringList>

#include <utility>
#include <vector>

namespace phonglab {

// Where the files of a student's page come from while the browser runs it
// (core/page/PageRun): the project's folder, then the course's library
// folders (Angel's Common/, webgl-utils, gl-matrix: the starter files a
// teacher has), then a map from outside addresses (a CDN's link) to local
// files. Everything else is refused: a page is untrusted code, and it gets
// no network and no file outside these folders.
struct PageFolders {
    QString project;       // the folder the page is in
    QStringList libraries; // looked up after the project, in order
    // (URL prefix, local file or folder): "https://cdn.jsdelivr.net/npm/three@0.91/build/" -> a folder
    std::vector<std::pair<QString, QString>> urlMap;
};

// The page's own origin: the project's folder is its root. A name that
// resolves nowhere (RFC 2606), answered by PageRun itself.
inline const QString kPageOrigin = QStringLiteral("http://student.phonglab.invalid");

struct ServedFile {
    QString path;    // the local file, canonical; empty when refused
    QString mime;    // its Content-Type
    QString refusal; // why not, for the report ("outside the project and the libraries")
    bool served() const { return !path.isEmpty(); }
};

// The file that answers `url`, or why none does. A path that climbs out of
// its folder (.., a symbolic link pointing out) is refused.
ServedFile serveRequest(const PageFolders &folders, const QString &url);

// The Content-Type a browser expects for a file of this name.
QString mimeTypeOfFile(const QString &fileName);

} // namespace phonglab
