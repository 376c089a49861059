#pragma once
#include "core/support/Result.h"

#include <QString>

namespace phonglab::cli {

// A .zip or .tar.gz as students and course platforms hand them in, unpacked
// with libarchive into a folder of PhongLab's own. Whatever the
// archive holds, nothing is written outside that folder: an archive with an
// absolute name, a `..` in a name, a link of any kind, a device, more
// entries or more bytes than the limits, a ratio no honest archive has (a
// zip bomb) or a damaged entry is refused whole, with the reason, and what
// was written of it is removed. Names are read as UTF-8 where they are, else
// as CP437 (what zip tools on Windows write).

struct ArchiveLimits {
    qint64 maxEntries = 10000;
    qint64 maxBytes = qint64(1) << 30; // unpacked, all entries together
    // Unpacked bytes per byte of archive beyond which it is a bomb (with at
    // least minBombBytes unpacked: a tiny text file compresses well too).
    qint64 maxRatio = 200;
    qint64 minBombBytes = qint64(64) << 20;
};

struct UnpackedArchive {
    qint64 entries = 0; // files and folders written
    qint64 bytes = 0;   // unpacked
};

bool isArchivePath(const QString &path); // .zip, .tar.gz, .tgz, .tar

// Unpacks `archive` into `folder` (made if need be; it should be empty).
Result<UnpackedArchive> unpackArchive(const QString &archive, const QString &folder,
                                      const ArchiveLimits &limits = {});

// A name from an archive as text: UTF-8 where the bytes are, else CP437.
QString archiveNameText(const QByteArray &raw);

} // namespace phonglab::cli
