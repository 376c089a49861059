#pragma once
#include "core/support/Language.h"

#include <QString>
#include <QStringList>

namespace phonglab {

// Where the shipped documentation is at run time: a folder holding README.md
// and docs/*.md (with docs/images/), as the source tree has them and as an
// install puts them in <prefix>/share/doc/phonglab. Searched in order:
// `first` (StartupOptions::documentationFolder, $PHONGLAB_DOC_DIR) when
// given; <exe dir>/../share/doc/phonglab; then beside the assets
// assetPath() finds: their parent (the source tree) and its ../doc/phonglab
// (an install's share/phonglab/assets → share/doc/phonglab). Unlike shaders
// and scenes the docs are not embedded: they are large and only read.
QStringList documentationSearchFolders(const QString &first);
// The first searched folder that holds the docs; empty when none does.
QString documentationFolder(const QString &first);
// The Markdown files of `folder` in the contents' order: README.md, then
// docs/*.md by name; the German pages (docs/de/, their README first) before
// them in a German run, after them in an English one. The first opens with F1.
QStringList documentationFiles(const QString &folder, const QString &language = currentLanguage());
// The first "# " heading of a Markdown file, else its file name.
QString documentTitle(const QString &markdownPath);

} // namespace phonglab
