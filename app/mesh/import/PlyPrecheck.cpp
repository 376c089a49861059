#include "PlyPrecheck.h"

#include "MeshTextTokens.h"
#include "PlyPrecheckBody.h"

#include <algorithm>

namespace phonglab {

namespace {

using meshtext::quoted;

// A header larger than this is not a mesh header.
constexpr qint64 kMaxHeaderBytes = 1 << 20;

using ply::PlyElement;
using ply::PlyHeader;
using ply::PlyProperty;
using ply::PlyType;
using ply::validateAscii;
using ply::walkBinary;

std::optional<PlyType> plyType(std::string_view n)
{
    if (n == "char" || n == "int8")
        return PlyType{1, true, true};
    if (n == "uchar" || n == "uint8")
        return PlyType{1, true, false};
    if (n == "short" || n == "int16")
        return PlyType{2, true, true};
    if (n == "ushort" || n == "uint16")
        return PlyType{2, true, false};
    if (n == "int" || n == "int32")
        return PlyType{4, true, true};
    if (n == "uint" || n == "uint32")
        return PlyType{4, true, false};
    if (n == "float" || n == "float32")
        return PlyType{4, false, true};
    if (n == "double" || n == "float64")
        return PlyType{8, false, true};
    return std::nullopt;
}

std::vector<std::string_view> words(std::string_view line)
{
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
            ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t')
            ++i;
        if (i > start)
            out.push_back(line.substr(start, i - start));
    }
    return out;
}

// "1.0" or "1": digits, optionally a point and more digits, short enough
// for a float (a version that overflows one fails operator>> just the same).
bool isPlainVersion(std::string_view v)
{
    if (v.size() > 8)
        return false;
    const auto digits = [&](std::size_t &i) {
        const std::size_t start = i;
        while (i < v.size() && v[i] >= '0' && v[i] <= '9')
            ++i;
        return i > start;
    };
    std::size_t i = 0;
    if (!digits(i))
        return false;
    if (i < v.size() && v[i] == '.') {
        ++i;
        if (!digits(i))
            return false;
    }
    return i == v.size();
}

// OpenMesh splits header words at any whitespace (form feeds and vertical
// tabs too) and reads counts with operator>>; a header word it cannot read
// sends it round its header loop forever. The header lines other than
// comments are text: the first control or non-ASCII byte is refused.
QString nonTextByteError(std::string_view line)
{
    const auto odd = std::find_if(line.begin(), line.end(), [](char c) {
        const auto u = static_cast<unsigned char>(c);
        return (u < 0x20 && c != '\t') || u > 0x7e;
    });
    if (odd == line.end())
        return {};
    return PlyPrecheckWords::tr(
               ": byte 0x%1 at column %2 is not text (a binary body before 'end_header'?)")
        .arg(static_cast<unsigned char>(*odd), 2, 16, QLatin1Char('0'))
        .arg(odd - line.begin() + 1);
}

// The errors below go after "PLY header line N".

QString parseFormatLine(const std::vector<std::string_view> &w, PlyHeader &h)
{
    if (h.format != PlyHeader::Unknown)
        return QStringLiteral(": a second 'format' line");
    if (w.size() < 2)
        return PlyPrecheckWords::tr(": 'format' without a format");
    if (w[1] == "ascii")
        h.format = PlyHeader::Ascii;
    else if (w[1] == "binary_little_endian")
        h.format = PlyHeader::LittleEndian;
    else if (w[1] == "binary_big_endian")
        h.format = PlyHeader::BigEndian;
    else
        return PlyPrecheckWords::tr(": unknown format %1").arg(quoted(w[1]));
    // OpenMesh reads the version with operator>>(float) and, on a failed read,
    // loops over the header forever; so accept only a plain number here.
    if (w.size() != 3 || !isPlainVersion(w[2]))
        return QStringLiteral(": expected 'format %1 1.0'")
            .arg(QString::fromLatin1(w[1].data(), int(w[1].size())));
    return {};
}

QString parseElementLine(const std::vector<std::string_view> &w, PlyHeader &h)
{
    std::int64_t count = -1;
    if (w.size() != 3 || !meshtext::parseInteger(w[2], count) || count < 0 || count > UINT32_MAX)
        return QStringLiteral(": expected 'element <name> <count>'");
    h.elements.push_back({std::string(w[1]), quint64(count), {}});
    return {};
}

QString parsePropertyLine(const std::vector<std::string_view> &w, PlyHeader &h)
{
    if (h.elements.empty())
        return PlyPrecheckWords::tr(": a property before any element");
    PlyProperty p;
    if (w.size() == 5 && w[1] == "list") {
        const auto countType = plyType(w[2]);
        const auto itemType = plyType(w[3]);
        if (!countType || !itemType || !countType->integer)
            return PlyPrecheckWords::tr(": unknown or unusable list types");
        p = {std::string(w[4]), *itemType, true, *countType};
    } else if (w.size() == 3) {
        const auto type = plyType(w[1]);
        if (!type)
            return PlyPrecheckWords::tr(": unknown property type %1").arg(quoted(w[1]));
        p = {std::string(w[2]), *type, false, {}};
    } else {
        return QStringLiteral(": expected 'property <type> <name>'");
    }
    h.elements.back().properties.push_back(std::move(p));
    return {};
}

QString parseHeader(std::string_view text, PlyHeader &h)
{
    std::size_t pos = 0;
    std::size_t lineNo = 0;
    while (pos < text.size()) {
        const std::size_t eol = text.find('\n', pos);
        if (eol == std::string_view::npos)
            break;
        std::string_view line = text.substr(pos, eol - pos);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        pos = eol + 1;
        ++lineNo;
        const QString where = PlyPrecheckWords::tr("PLY header line %1").arg(lineNo);
        if (lineNo == 1) {
            if (line != "ply")
                return PlyPrecheckWords::tr("not a PLY file (it does not start with 'ply')");
            continue;
        }
        const std::vector<std::string_view> w = words(line);
        if (w.empty() || w[0] == "comment" || w[0] == "obj_info")
            continue; // OpenMesh skips the rest of these lines, whatever they hold
        if (const QString odd = nonTextByteError(line); !odd.isEmpty())
            return where + odd;
        QString error;
        if (w[0] == "format") {
            error = parseFormatLine(w, h);
        } else if (w[0] == "element") {
            error = parseElementLine(w, h);
        } else if (w[0] == "property") {
            error = parsePropertyLine(w, h);
        } else if (w[0] == "end_header") {
            if (w.size() != 1)
                return where + PlyPrecheckWords::tr(": words after 'end_header'");
            if (h.format == PlyHeader::Unknown)
                return PlyPrecheckWords::tr("the PLY header has no 'format' line");
            h.bodyOffset = qint64(pos);
            h.bodyLine = lineNo + 1;
            return {};
        } else {
            return where + PlyPrecheckWords::tr(": unknown keyword %1").arg(quoted(w[0]));
        }
        if (!error.isEmpty())
            return where + error;
    }
    return PlyPrecheckWords::tr(
        "the PLY header has no 'end_header' line (truncated or not a PLY file)");
}

const PlyElement *findElement(const PlyHeader &h, std::string_view name)
{
    for (const PlyElement &e : h.elements)
        if (e.name == name)
            return &e;
    return nullptr;
}

bool hasScalar(const PlyElement &e, std::string_view name)
{
    for (const PlyProperty &p : e.properties)
        if (p.name == name && !p.isList)
            return true;
    return false;
}

bool hasFaceIndices(const PlyElement &e)
{
    for (const PlyProperty &p : e.properties)
        if (p.isList && (p.name == "vertex_indices" || p.name == "vertex_index"))
            return true;
    return false;
}

// What each element needs at the least: its scalars and list lengths in
// binary, a digit and a separator per value in ascii. A header claiming more
// than the file can hold is refused here, before any allocation.
QString checkElementsFit(const PlyHeader &h, bool binary, quint64 bodyBytes)
{
    quint64 needed = 0;
    for (const PlyElement &e : h.elements) {
        quint64 perElement = 0;
        for (const PlyProperty &p : e.properties)
            perElement += binary ? quint64(p.isList ? p.countType.size : p.type.size) : 2;
        needed += e.count * perElement;
        if (needed > bodyBytes + 1)
            return PlyPrecheckWords::tr(
                       "the header declares %1 %2 elements, which need at least %3 bytes, "
                       "but the file has %4 bytes after the header (truncated or corrupt)")
                .arg(e.count)
                .arg(QString::fromStdString(e.name))
                .arg(needed)
                .arg(bodyBytes);
    }
    return {};
}

} // namespace

void precheckPly(const QString &path, MeshFilePrecheck &check)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        check.error = PlyPrecheckWords::tr("cannot open the file: %1").arg(file.errorString());
        return;
    }
    const QByteArray head = file.read(std::min(check.fileSize, kMaxHeaderBytes));
    PlyHeader h;
    check.error = parseHeader(std::string_view(head.constData(), std::size_t(head.size())), h);
    if (!check.ok())
        return;

    const PlyElement *vertex = findElement(h, "vertex");
    if (!vertex || !hasScalar(*vertex, "x") || !hasScalar(*vertex, "y")
        || !hasScalar(*vertex, "z")) {
        check.error = PlyPrecheckWords::tr("the PLY file has no vertex element with x, y and z");
        return;
    }
    const PlyElement *face = findElement(h, "face");
    if (!face || face->count == 0 || !hasFaceIndices(*face)) {
        check.error = PlyPrecheckWords::tr("the PLY file has no faces (a point cloud?)");
        return;
    }
    check.binary = h.format != PlyHeader::Ascii;
    check.declaredVertices = vertex->count;
    check.declaredFaces = face->count;

    check.error = checkElementsFit(h, check.binary, quint64(check.fileSize - h.bodyOffset));
    if (!check.ok())
        return;

    if (check.binary) {
        walkBinary(file, h, check);
        return;
    }
    file.close();
    std::string bytes;
    if (!readWholeFile(path, bytes, check.error))
        return;
    const std::string_view body = std::string_view(bytes).substr(std::size_t(h.bodyOffset));
    if (body.find('\0') != std::string_view::npos) {
        check.error = PlyPrecheckWords::tr("an ascii PLY file with binary data in it (a NUL byte)");
        return;
    }
    validateAscii(body, h, check);
}

} // namespace phonglab
