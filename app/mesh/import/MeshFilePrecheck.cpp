#include "MeshFilePrecheck.h"

#include "ByteOrder.h"
#include "MeshTextTokens.h"
#include "OffPrecheck.h"
#include "OmPrecheck.h"
#include "PlyPrecheck.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct MeshFilePrecheckWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::MeshFilePrecheck)
};

namespace {

using meshtext::quoted;

constexpr qint64 kSampleBytes = 64 * 1024;

bool startsWith(std::string_view s, std::string_view prefix)
{
    return s.substr(0, prefix.size()) == prefix;
}

bool startsWithSolid(std::string_view head)
{
    const std::size_t first = head.find_first_not_of(" \t\r\n");
    return first != std::string_view::npos && head.size() - first >= 5
        && qstrnicmp(head.data() + first, "solid", 5) == 0;
}

// The known format a file starts like, for "this is X, not Y" errors (a
// PLY renamed to .obj, a zipped download, a saved web page), and what to do.
struct Sniffed {
    QString what;
    QString hint;
};

Sniffed sniffFormat(std::string_view head)
{
    struct Magic {
        std::string_view bytes;
        const char *what;
        const char *hint;
    };
    static constexpr Magic kMagics[] = {
        {"ply\n", "a PLY file", "rename it to .ply"},
        {"ply\r\n", "a PLY file", "rename it to .ply"},
        {"OMT", "an OpenMesh file", "rename it to .om"},
        {"OMQ", "an OpenMesh file", "rename it to .om"},
        {"OMP", "an OpenMesh file", "rename it to .om"},
        {"\x89PNG", "a PNG image", ""},
        {"\xFF\xD8\xFF", "a JPEG image", ""},
        {"GIF8", "a GIF image", ""},
        {"PK\x03\x04", "a ZIP archive", "unpack it first"},
        {"\x1F\x8B", "a gzip-compressed file", "unpack it first"},
        {"7z\xBC\xAF", "a 7-Zip archive", "unpack it first"},
        {"glTF", "a binary glTF file", ""},
        {"Kaydara FBX Binary", "an FBX file", ""},
        {"%PDF", "a PDF document", ""},
    };
    for (const Magic &m : kMagics)
        if (startsWith(head, m.bytes))
            return {QString::fromLatin1(m.what), QString::fromLatin1(m.hint)};
    if (offHeaderAt(head))
        return {QStringLiteral("an OFF file"), MeshFilePrecheckWords::tr("rename it to .off")};
    if (startsWithSolid(head))
        return {MeshFilePrecheckWords::tr("an ascii STL file"),
                MeshFilePrecheckWords::tr("rename it to .stl")};
    const std::size_t first = head.find_first_not_of(" \t\r\n");
    if (first != std::string_view::npos && head[first] == '{')
        return {QStringLiteral("a JSON file"), {}};
    if (first != std::string_view::npos && head[first] == '<')
        return {QStringLiteral("an XML or HTML file"), {}};
    return {};
}

QString suffixOf(MeshFileFormat format)
{
    switch (format) {
    case MeshFileFormat::Obj: return QStringLiteral(".obj");
    case MeshFileFormat::Ply: return QStringLiteral(".ply");
    case MeshFileFormat::Off: return QStringLiteral(".off");
    case MeshFileFormat::Stl: return QStringLiteral(".stl");
    case MeshFileFormat::Om: return QStringLiteral(".om");
    }
    return {};
}

// The error for a file that does not start the way its format must: named
// after what it looks like instead, when we recognise that.
QString wrongMagic(std::string_view head, MeshFileFormat format, const QString &expected)
{
    const Sniffed other = sniffFormat(head);
    if (other.what.isEmpty())
        return expected;
    const QString error =
        MeshFilePrecheckWords::tr("this is %1, not a %2 file").arg(other.what, suffixOf(format));
    return other.hint.isEmpty() ? error : QStringLiteral("%1 (%2)").arg(error, other.hint);
}

void checkObj(std::string_view head, MeshFilePrecheck &check)
{
    // OBJ has no magic; anything another format starts with is not OBJ.
    check.error = wrongMagic(head, check.format, {});
    if (check.ok())
        check.error = meshtext::binaryDataError(head, QStringLiteral("OBJ"));
}

void validateAsciiStl(std::string_view text, MeshFilePrecheck &check)
{
    // Mirrors OpenMesh's ascii STL reader: a line holding "facet normal" has
    // three numbers after those words; a line holding "outer" (or "OUTER")
    // is followed by three lines of a word and three numbers, the vertices.
    // The reader takes those lines unseen, so each is checked here.
    check.error = meshtext::binaryDataError(text, QStringLiteral("ascii STL"));
    if (!check.ok())
        return;
    std::size_t pos = 0;
    std::size_t lineNo = 0;
    std::string_view line;
    auto nextLine = [&] {
        if (pos >= text.size())
            return false;
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos)
            end = text.size();
        line = text.substr(pos, end - pos);
        pos = end + 1;
        ++lineNo;
        return true;
    };
    auto numbersAfter = [&](int skipWords, const QString &what) {
        meshtext::TextTokens tokens(line, lineNo);
        for (int i = 0; i < skipWords; ++i)
            tokens.nextOnLine();
        for (int i = 0; i < 3; ++i) {
            const std::string_view t = tokens.nextOnLine();
            if (!meshtext::isReal(t)) {
                check.error = QStringLiteral("line %1: expected %2, found %3")
                                  .arg(lineNo)
                                  .arg(what, quoted(t));
                return false;
            }
        }
        return true;
    };
    quint64 facets = 0;
    while (nextLine()) {
        if (line.find("facet normal") != std::string_view::npos
            && !numbersAfter(2, MeshFilePrecheckWords::tr("three numbers after 'facet normal'")))
            return;
        if (line.find("outer") == std::string_view::npos
            && line.find("OUTER") == std::string_view::npos)
            continue;
        for (int corner = 0; corner < 3; ++corner) {
            if (!nextLine()) {
                check.error =
                    MeshFilePrecheckWords::tr("the file ends inside facet %1 (truncated?)")
                        .arg(facets + 1);
                return;
            }
            if (!numbersAfter(1, MeshFilePrecheckWords::tr("'vertex x y z'")))
                return;
        }
        ++facets;
    }
    if (facets == 0)
        check.error = MeshFilePrecheckWords::tr("the STL file has no facets");
    check.declaredFaces = facets;
}

void dropNonFiniteTriangles(const QString &path, MeshFilePrecheck &check)
{
    // OpenMesh's STL reader merges corners by position in a std::map; a NaN
    // compares equivalent to any key there and silently takes some other
    // corner's place. Such triangles are cut out of a copy the reader gets.
    std::string bytes;
    if (!readWholeFile(path, bytes, check.error))
        return;
    const std::size_t triangles = std::size_t(check.declaredFaces);
    auto finite = [&](std::size_t t) {
        float corners[9];
        std::memcpy(corners, bytes.data() + 84 + 50 * t + 12, sizeof corners);
        return std::all_of(std::begin(corners), std::end(corners),
                           [](float f) { return std::isfinite(f); });
    };
    std::size_t bad = 0;
    for (std::size_t t = 0; t < triangles; ++t)
        bad += finite(t) ? 0 : 1;
    if (bad == 0)
        return;
    std::string kept = bytes.substr(0, 84);
    kept.reserve(84 + 50 * (triangles - bad));
    for (std::size_t t = 0; t < triangles; ++t)
        if (finite(t))
            kept.append(bytes, 84 + 50 * t, 50);
    const std::uint32_t count = std::uint32_t(triangles - bad);
    for (int i = 0; i < 4; ++i)
        kept[80 + i] = char((count >> (8 * i)) & 0xff);
    check.rewritten = std::move(kept);
    check.declaredFaces = count;
    check.warnings << MeshFilePrecheckWords::tr("dropped %1 with NaN or infinite coordinates")
                          .arg(meshtext::counted(
                              bad, QT_TRANSLATE_NOOP("phonglab::MeshText", "triangle"),
                              QT_TRANSLATE_NOOP("phonglab::MeshText", "triangles")));
    if (count == 0)
        check.error = MeshFilePrecheckWords::tr("every triangle has NaN or infinite coordinates");
}

void checkStl(const QString &path, std::string_view head, MeshFilePrecheck &check)
{
    // Binary STL: an 80-byte header, a triangle count, 50 bytes a triangle.
    // Plenty of exporters start that header with "solid", so a size that
    // matches the count exactly decides for binary before the keyword does.
    const qint64 size = check.fileSize;
    const qint64 expected = size >= 84 ? 84 + 50 * qint64(littleEndian(head, 80)) : -1;
    if (size != expected && startsWithSolid(head)) {
        std::string text;
        if (readWholeFile(path, text, check.error))
            validateAsciiStl(text, check);
        return;
    }
    if (size != expected) {
        check.error = wrongMagic(head, check.format, {});
        if (!check.ok())
            return;
        if (size < 84) {
            check.error = MeshFilePrecheckWords::tr(
                              "too small for a binary STL file (%1 bytes) and not an ascii one")
                              .arg(size);
            return;
        }
        if (size < expected) {
            check.error =
                MeshFilePrecheckWords::tr(
                    "the binary STL header declares %1 triangles (%2 bytes) but the file has "
                    "only %3 bytes (truncated or not an STL file)")
                    .arg((expected - 84) / 50)
                    .arg(expected)
                    .arg(size);
            return;
        }
        check.warnings << MeshFilePrecheckWords::tr("ignored %1 after the last triangle")
                              .arg(meshtext::counted(
                                  size - expected, QT_TRANSLATE_NOOP("phonglab::MeshText", "byte"),
                                  QT_TRANSLATE_NOOP("phonglab::MeshText", "bytes")));
    }
    check.binary = true;
    check.declaredFaces = quint64(expected - 84) / 50;
    if (check.declaredFaces == 0)
        check.error = MeshFilePrecheckWords::tr("the STL file has no triangles");
    else
        dropNonFiniteTriangles(path, check);
}

void checkOm(const QString &path, std::string_view head, MeshFilePrecheck &check)
{
    if (head.size() < 16 || !startsWith(head, "OM") || !std::strchr("TQP", head[2]))
        check.error = wrongMagic(
            head, check.format,
            MeshFilePrecheckWords::tr("not an OpenMesh file (it does not start with 'OM')"));
    else
        precheckOm(path, check);
}

} // namespace

std::optional<MeshFileFormat> meshFileFormatForPath(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("obj"))
        return MeshFileFormat::Obj;
    if (suffix == QLatin1String("ply"))
        return MeshFileFormat::Ply;
    if (suffix == QLatin1String("off"))
        return MeshFileFormat::Off;
    if (suffix == QLatin1String("stl"))
        return MeshFileFormat::Stl;
    if (suffix == QLatin1String("om"))
        return MeshFileFormat::Om;
    return std::nullopt;
}

QString supportedMeshFileSuffixes()
{
    return QStringLiteral(".obj, .ply, .off, .stl, .om");
}

MeshFilePrecheck precheckMeshFile(const QString &path, MeshFileFormat format)
{
    MeshFilePrecheck check;
    check.format = format;
    const QFileInfo info(path);
    if (!info.exists()) {
        check.error = MeshFilePrecheckWords::tr("file not found");
        return check;
    }
    if (!info.isFile()) {
        check.error = MeshFilePrecheckWords::tr("not a regular file");
        return check;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        check.error = MeshFilePrecheckWords::tr("cannot open the file: %1").arg(file.errorString());
        return check;
    }
    check.fileSize = file.size();
    if (check.fileSize == 0) {
        check.error = MeshFilePrecheckWords::tr("the file is empty");
        return check;
    }
    if (check.fileSize > kMaxMeshFileBytes) {
        check.error =
            MeshFilePrecheckWords::tr("the file is too large (%1 MiB; the limit is %2 MiB)")
                .arg(check.fileSize >> 20)
                .arg(kMaxMeshFileBytes >> 20);
        return check;
    }
    const QByteArray headBytes = file.read(kSampleBytes);
    if (headBytes.isEmpty()) {
        check.error = MeshFilePrecheckWords::tr("cannot read the file: %1").arg(file.errorString());
        return check;
    }
    file.close();
    const std::string_view head(headBytes.constData(), std::size_t(headBytes.size()));

    switch (format) {
    case MeshFileFormat::Obj: checkObj(head, check); break;
    case MeshFileFormat::Ply:
        if (!startsWith(head, "ply\n") && !startsWith(head, "ply\r\n"))
            check.error = wrongMagic(
                head, format,
                MeshFilePrecheckWords::tr("not a PLY file (it does not start with 'ply')"));
        else
            precheckPly(path, check);
        break;
    case MeshFileFormat::Off:
        if (!offHeaderAt(head))
            check.error = wrongMagic(head, format,
                                     MeshFilePrecheckWords::tr(
                                         "not an OFF file (it does not start with an OFF header)"));
        else
            precheckOff(path, check);
        break;
    case MeshFileFormat::Stl: checkStl(path, head, check); break;
    case MeshFileFormat::Om: checkOm(path, head, check); break;
    }
    return check;
}

bool readWholeFile(const QString &path, std::string &bytes, QString &error,
                   const std::function<bool(double)> &progress)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        error = MeshFilePrecheckWords::tr("cannot open the file: %1").arg(file.errorString());
        return false;
    }
    const qint64 size = file.size();
    if (size > kMaxMeshFileBytes) {
        error = MeshFilePrecheckWords::tr("the file is too large (%1 MiB; the limit is %2 MiB)")
                    .arg(size >> 20)
                    .arg(kMaxMeshFileBytes >> 20);
        return false;
    }
    bytes.resize(std::size_t(size));
    constexpr qint64 kChunk = 16 << 20;
    qint64 done = 0;
    while (done < size) {
        const qint64 n = file.read(bytes.data() + done, std::min(kChunk, size - done));
        if (n <= 0) {
            error = n < 0
                ? MeshFilePrecheckWords::tr("cannot read the file: %1").arg(file.errorString())
                : MeshFilePrecheckWords::tr("the file got shorter while it was read");
            return false;
        }
        done += n;
        if (progress && !progress(double(done) / double(size))) {
            error = QStringLiteral("cancelled");
            return false;
        }
    }
    return true;
}

} // namespace phonglab
