#include "SubmissionArchive.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStringDecoder>

#include <archive.h>
#include <archive_entry.h>

#include <memory>
#include <optional>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct SubmissionArchiveWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::SubmissionArchive)
};

namespace {

// CP437's upper half (the lower is ASCII).
constexpr char16_t kCp437High[128] = {
    0x00C7, 0x00FC, 0x00E9, 0x00E2, 0x00E4, 0x00E0, 0x00E5, 0x00E7, 0x00EA, 0x00EB, 0x00E8, 0x00EF,
    0x00EE, 0x00EC, 0x00C4, 0x00C5, 0x00C9, 0x00E6, 0x00C6, 0x00F4, 0x00F6, 0x00F2, 0x00FB, 0x00F9,
    0x00FF, 0x00D6, 0x00DC, 0x00A2, 0x00A3, 0x00A5, 0x20A7, 0x0192, 0x00E1, 0x00ED, 0x00F3, 0x00FA,
    0x00F1, 0x00D1, 0x00AA, 0x00BA, 0x00BF, 0x2310, 0x00AC, 0x00BD, 0x00BC, 0x00A1, 0x00AB, 0x00BB,
    0x2591, 0x2592, 0x2593, 0x2502, 0x2524, 0x2561, 0x2562, 0x2556, 0x2555, 0x2563, 0x2551, 0x2557,
    0x255D, 0x255C, 0x255B, 0x2510, 0x2514, 0x2534, 0x252C, 0x251C, 0x2500, 0x253C, 0x255E, 0x255F,
    0x255A, 0x2554, 0x2569, 0x2566, 0x2560, 0x2550, 0x256C, 0x2567, 0x2568, 0x2564, 0x2565, 0x2559,
    0x2558, 0x2552, 0x2553, 0x256B, 0x256A, 0x2518, 0x250C, 0x2588, 0x2584, 0x258C, 0x2590, 0x2580,
    0x03B1, 0x00DF, 0x0393, 0x03C0, 0x03A3, 0x03C3, 0x00B5, 0x03C4, 0x03A6, 0x0398, 0x03A9, 0x03B4,
    0x221E, 0x03C6, 0x03B5, 0x2229, 0x2261, 0x00B1, 0x2265, 0x2264, 0x2320, 0x2321, 0x00F7, 0x2248,
    0x00B0, 0x2219, 0x00B7, 0x221A, 0x207F, 0x00B2, 0x25A0, 0x00A0};

struct ArchiveCloser {
    void operator()(archive *a) const { archive_read_free(a); }
};

// The entry's name, checked: relative, no `..`, no empty or `.` part, `\`
// read as a separator. Empty where it may not be written.
QString safeRelativeName(const QString &name)
{
    QString n = name;
    n.replace(QLatin1Char('\\'), QLatin1Char('/'));
    if (n.startsWith(QLatin1Char('/')) || (n.size() > 1 && n[1] == QLatin1Char(':')))
        return {};
    QStringList parts;
    for (const QString &part : n.split(QLatin1Char('/'), Qt::SkipEmptyParts)) {
        if (part == QLatin1String(".."))
            return {};
        if (part != QLatin1String("."))
            parts << part;
    }
    return parts.join(QLatin1Char('/'));
}

QString entryName(archive_entry *entry)
{
    if (const char *raw = archive_entry_pathname(entry))
        return archiveNameText(QByteArray(raw));
    if (const char *utf8 = archive_entry_pathname_utf8(entry))
        return QString::fromUtf8(utf8);
    return {};
}

} // namespace

bool isArchivePath(const QString &path)
{
    const QString lower = path.toLower();
    for (const char *suffix : {".zip", ".tar.gz", ".tgz", ".tar"})
        if (lower.endsWith(QLatin1String(suffix)))
            return true;
    return false;
}

QString archiveNameText(const QByteArray &raw)
{
    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    const QString text = utf8.decode(raw);
    if (!utf8.hasError())
        return text;
    QString cp437;
    for (const char c : raw) {
        const auto b = static_cast<unsigned char>(c);
        cp437 += b < 0x80 ? QChar(b) : QChar(kCp437High[b - 0x80]);
    }
    return cp437;
}

namespace {

// What an entry asks for: refused (why), nothing left to write (the folder
// itself, or a folder now made), or the plain file `file` (relative, its
// folder made).
struct EntryTarget {
    std::optional<QString> refusal;
    QString file;
};

// The checks on an entry's name and type, in the order they refuse; makes
// the folders it needs inside `root`.
EntryTarget entryTarget(archive_entry *entry, const QDir &root)
{
    const QString raw = entryName(entry);
    const QString relative = safeRelativeName(raw);
    const mode_t type = archive_entry_filetype(entry);
    if (relative.isEmpty() && type == AE_IFDIR && !raw.contains(QLatin1String("..")))
        return {}; // "./": the folder itself
    if (relative.isEmpty())
        return {
            SubmissionArchiveWords::tr("the name %1 leaves the folder it is unpacked in").arg(raw),
            {}};
    if (archive_entry_hardlink(entry) || type == AE_IFLNK)
        return {SubmissionArchiveWords::tr("%1 is a link").arg(relative), {}};
    if (type == AE_IFDIR) {
        if (!root.mkpath(relative))
            return {SubmissionArchiveWords::tr("cannot make %1").arg(relative), {}};
        return {};
    }
    if (type != AE_IFREG)
        return {SubmissionArchiveWords::tr("%1 is not a plain file").arg(relative), {}};
    if (!root.mkpath(QFileInfo(relative).path()))
        return {SubmissionArchiveWords::tr("cannot make %1").arg(relative), {}};
    return {std::nullopt, relative};
}

// One archive being read, and what it has unpacked so far against its limits.
struct Unpacking {
    archive *a = nullptr;
    const ArchiveLimits &limits;
    qint64 archiveBytes = 1;
    std::vector<char> buffer;
    UnpackedArchive done;
};

// The current entry's bytes into `out`; why it is refused, if it is. The
// limits are checked before each block is written, so a bomb stops early.
std::optional<QString> copyEntryData(Unpacking &u, QFile &out, const QString &relative)
{
    for (;;) {
        const la_ssize_t n = archive_read_data(u.a, u.buffer.data(), u.buffer.size());
        if (n == 0)
            break;
        if (n < 0)
            return SubmissionArchiveWords::tr("it is damaged at %1 (%2)")
                .arg(relative, QString::fromLocal8Bit(archive_error_string(u.a)));
        u.done.bytes += n;
        if (u.done.bytes > u.limits.maxBytes)
            return SubmissionArchiveWords::tr("more than %1 MiB unpacked")
                .arg(u.limits.maxBytes >> 20);
        if (u.done.bytes > u.limits.minBombBytes
            && u.done.bytes / u.archiveBytes > u.limits.maxRatio)
            return SubmissionArchiveWords::tr(
                       "a zip bomb: %1 MiB unpacked from %2 KiB and still going")
                .arg(u.done.bytes >> 20)
                .arg(u.archiveBytes >> 10);
        if (out.write(u.buffer.data(), n) != n)
            return SubmissionArchiveWords::tr("cannot write %1").arg(relative);
    }
    return std::nullopt;
}

} // namespace

Result<UnpackedArchive> unpackArchive(const QString &archivePath, const QString &folder,
                                      const ArchiveLimits &limits)
{
    const QString name = QFileInfo(archivePath).fileName();
    const auto refuse = [&](const QString &why) -> Result<UnpackedArchive> {
        QDir(folder).removeRecursively(); // nothing of a refused archive stays
        return fail(SubmissionArchiveWords::tr("%1: refused: %2").arg(name, why));
    };
    std::unique_ptr<archive, ArchiveCloser> a(archive_read_new());
    archive_read_support_filter_gzip(a.get());
    archive_read_support_format_zip(a.get());
    archive_read_support_format_tar(a.get());
    if (archive_read_open_filename(a.get(), QFile::encodeName(archivePath).constData(), 64 * 1024)
        != ARCHIVE_OK)
        return fail(SubmissionArchiveWords::tr("%1: cannot read it as an archive: %2")
                        .arg(name, QString::fromLocal8Bit(archive_error_string(a.get()))));
    if (!QDir().mkpath(folder))
        return fail(SubmissionArchiveWords::tr("%1: cannot make the folder %2").arg(name, folder));
    const QDir root(folder);
    const qint64 archiveBytes = std::max<qint64>(1, QFileInfo(archivePath).size());
    Unpacking u{a.get(), limits, archiveBytes, std::vector<char>(64 * 1024), UnpackedArchive()};
    archive_entry *entry = nullptr;
    for (;;) {
        const int header = archive_read_next_header(a.get(), &entry);
        if (header == ARCHIVE_EOF)
            break;
        if (header != ARCHIVE_OK && header != ARCHIVE_WARN)
            return refuse(SubmissionArchiveWords::tr("it is damaged (%1)")
                              .arg(QString::fromLocal8Bit(archive_error_string(a.get()))));
        if (++u.done.entries > limits.maxEntries)
            return refuse(
                SubmissionArchiveWords::tr("more than %1 entries").arg(limits.maxEntries));
        const EntryTarget t = entryTarget(entry, root);
        if (t.refusal)
            return refuse(*t.refusal);
        if (t.file.isEmpty())
            continue;
        const QString target = root.filePath(t.file);
        // A folder made above may never be a link: the archive has none, and
        // the folder was PhongLab's own and empty.
        QFile out(target);
        if (QFileInfo(target).isSymLink() || !out.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return refuse(SubmissionArchiveWords::tr("cannot write %1").arg(t.file));
        // `out` stays open until a refusal has removed the folder, as before the split.
        if (const std::optional<QString> why = copyEntryData(u, out, t.file))
            return refuse(*why);
    }
    return u.done;
}

} // namespace phonglab::cli
