#include "OffPrecheck.h"

#include "ByteOrder.h"
#include "MeshTextTokens.h"

#include <QCoreApplication>
#include <vector>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct OffPrecheckWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::OffPrecheck)
};

namespace {

using meshtext::quoted;

struct OffKeyword {
    bool ok = false;
    bool normals = false;
    bool colors = false;
    bool higherDimension = false;
    std::string_view keyword; // e.g. "COFF"
    std::string_view rest;    // whatever follows "OFF" in the same token
};

OffKeyword parseKeyword(std::string_view token)
{
    OffKeyword k;
    std::string_view t = token;
    if (t.substr(0, 2) == "ST")
        t.remove_prefix(2);
    if (!t.empty() && t[0] == 'C') {
        k.colors = true;
        t.remove_prefix(1);
    }
    if (!t.empty() && t[0] == 'N') {
        k.normals = true;
        t.remove_prefix(1);
    }
    while (!t.empty() && (t[0] == '4' || t[0] == 'n')) {
        k.higherDimension = true;
        t.remove_prefix(1);
    }
    if (t.substr(0, 3) != "OFF")
        return k;
    k.keyword = token.substr(0, token.size() - t.size() + 3);
    k.rest = t.substr(3);
    k.ok = k.rest.empty() || std::isdigit(static_cast<unsigned char>(k.rest[0]));
    return k;
}

// OpenMesh reads a binary face as a corner count and that many indices,
// growing its index list one read at a time, past the end of the file if the
// count says so: a count of 10^9 asks for gigabytes. Walk the faces first.
QString checkBinaryFaces(std::string_view text, std::size_t at, quint64 faces)
{
    for (quint64 f = 0; f < faces; ++f) {
        if (text.size() - at < 4)
            return OffPrecheckWords::tr(
                       "the binary OFF file ends after %1 of %2 faces (truncated?)")
                .arg(f)
                .arg(faces);
        const quint64 corners = littleEndian(text, at);
        at += 4;
        if (corners > (text.size() - at) / 4)
            return OffPrecheckWords::tr(
                       "binary OFF face %1 (byte %2) declares %3 corners, more than the %4 bytes "
                       "left can hold (corrupt?)")
                .arg(f + 1)
                .arg(at - 4)
                .arg(corners)
                .arg(text.size() - at);
        at += 4 * corners;
    }
    return {};
}

void checkBinary(std::string_view text, const OffKeyword &k, MeshFilePrecheck &check)
{
    // "OFF BINARY": the counts and values follow the first line as 32-bit
    // numbers (OpenMesh reads them little-endian).
    const std::size_t body = text.find('\n') + 1;
    if (body == 0 || text.size() < body + 12) {
        check.error = OffPrecheckWords::tr("the binary OFF file ends before its counts");
        return;
    }
    // Colour and texture layouts depend on reader options this check cannot
    // see, so the faces could not be walked safely.
    if (k.colors || k.keyword.substr(0, 2) == "ST") {
        check.error =
            OffPrecheckWords::tr(
                "binary %1 files (with colours or texture coordinates) are not supported; "
                "save it as ascii OFF or as PLY")
                .arg(QString::fromLatin1(k.keyword.data(), qsizetype(k.keyword.size())));
        return;
    }
    check.binary = true;
    check.declaredVertices = littleEndian(text, body);
    check.declaredFaces = littleEndian(text, body + 4);
    const quint64 vertexBytes = check.declaredVertices * (k.normals ? 24 : 12);
    const quint64 needed = body + 12 + vertexBytes + check.declaredFaces * 16;
    if (needed > text.size())
        check.error =
            OffPrecheckWords::tr(
                "the binary OFF header declares %1 vertices and %2 faces, which need at least "
                "%3 bytes, but the file has %4 (truncated or corrupt)")
                .arg(check.declaredVertices)
                .arg(check.declaredFaces)
                .arg(needed)
                .arg(text.size());
    else if (check.declaredFaces == 0)
        check.error = OffPrecheckWords::tr("the OFF file has no faces");
    else
        check.error = checkBinaryFaces(text, body + 12 + vertexBytes, check.declaredFaces);
}

void appendLine(std::string &out, const std::vector<std::string_view> &tokens, std::size_t count)
{
    for (std::size_t i = 0; i < count; ++i) {
        if (i)
            out += ' ';
        out += tokens[i];
    }
    out += '\n';
}

struct OffCounts {
    std::int64_t values[3] = {}; // vertices, faces, edges
    bool onHeaderLine = false;   // a count shares the header keyword's line
};

// The counts come from the rest of the keyword token ("OFF1234", as
// ModelNet writes it) or the words after it, on any line.
QString readCounts(meshtext::TextTokens &tokens, const OffKeyword &k, std::size_t headerLine,
                   OffCounts &counts)
{
    for (int i = 0; i < 3; ++i) {
        const std::string_view t = (i == 0 && !k.rest.empty()) ? k.rest : tokens.next();
        std::int64_t &count = counts.values[i];
        if (!meshtext::parseInteger(t, count) || count < 0 || count > UINT32_MAX)
            return OffPrecheckWords::tr(
                       "line %1: expected the vertex, face and edge counts, found %2")
                .arg(tokens.line())
                .arg(quoted(t));
        counts.onHeaderLine = counts.onHeaderLine || tokens.line() == headerLine;
    }
    if (!tokens.lineIsEmpty())
        return OffPrecheckWords::tr("line %1: unexpected text after the counts").arg(tokens.line());
    return {};
}

QString checkDeclaredCounts(std::size_t fileSize, const MeshFilePrecheck &check)
{
    // At the least "0 0 0\n" a vertex and "3 0 0 0\n" a face.
    const quint64 needed = 6 * check.declaredVertices + 8 * check.declaredFaces;
    if (needed > fileSize)
        return OffPrecheckWords::tr(
                   "the OFF header declares %1 vertices and %2 faces, which need at least %3 "
                   "bytes, but the file has %4 (truncated or corrupt)")
            .arg(check.declaredVertices)
            .arg(check.declaredFaces)
            .arg(needed)
            .arg(fileSize);
    if (check.declaredFaces == 0)
        return OffPrecheckWords::tr("the OFF file has no faces");
    return {};
}

// The cleaned copy puts the keyword and the counts on lines of their own,
// the only header layout the reader takes.
std::string startCleanCopy(const OffKeyword &k, const OffCounts &counts, std::size_t fileSize)
{
    std::string out;
    out.reserve(fileSize);
    out.append(k.keyword).append("\n");
    out.append(std::to_string(counts.values[0]))
        .append(" ")
        .append(std::to_string(counts.values[1]))
        .append(" ")
        .append(std::to_string(counts.values[2]))
        .append("\n");
    return out;
}

// The body read one non-blank line at a time, as the reader takes it.
struct OffLines {
    meshtext::TextTokens &tokens;
    std::vector<std::string_view> line; // the current line's tokens

    // Moves to the next line with a token; false at the end of the file.
    bool readLine()
    {
        tokens.nextLine();
        while (!tokens.atEnd() && tokens.lineIsEmpty())
            tokens.nextLine();
        line.clear();
        for (std::string_view t = tokens.nextOnLine(); !t.empty(); t = tokens.nextOnLine())
            line.push_back(t);
        return !line.empty();
    }

    QString atLine(const QString &message) const
    {
        return QStringLiteral("line %1: %2").arg(tokens.line()).arg(message);
    }
};

QString readVertices(OffLines &lines, const OffKeyword &k, std::int64_t declared, std::string &out)
{
    const std::size_t vertexNumbers = k.normals ? 6 : 3;
    for (quint64 v = 0; v < quint64(declared); ++v) {
        if (!lines.readLine())
            return OffPrecheckWords::tr("the file ends after %1 of %2 vertices (truncated?)")
                .arg(v)
                .arg(declared);
        const std::vector<std::string_view> &line = lines.line;
        if (line.size() < vertexNumbers)
            return lines.atLine(OffPrecheckWords::tr("vertex %1 needs %2 numbers, found %3")
                                    .arg(v + 1)
                                    .arg(vertexNumbers)
                                    .arg(line.size()));
        for (std::string_view t : line)
            if (!meshtext::isReal(t))
                return lines.atLine(
                    OffPrecheckWords::tr("expected a number, found %1").arg(quoted(t)));
        appendLine(out, line, line.size());
    }
    return {};
}

// What is wrong with face `f`'s line, if anything: its corner count, then
// each index and each value after them. Sets indicesEnd, the position after
// the last index.
QString checkFaceLine(const std::vector<std::string_view> &line, quint64 f, std::size_t &indicesEnd)
{
    std::int64_t corners = -1;
    if (!meshtext::parseInteger(line[0], corners) || corners < 0)
        return OffPrecheckWords::tr("expected the corner count of face %1, found %2")
            .arg(f + 1)
            .arg(quoted(line[0]));
    if (std::size_t(corners) > line.size() - 1)
        return OffPrecheckWords::tr("face %1 has %2 corners but only %3 indices")
            .arg(f + 1)
            .arg(corners)
            .arg(line.size() - 1);
    indicesEnd = std::size_t(corners) + 1;
    for (std::size_t i = 1; i < line.size(); ++i) {
        const bool index = i < indicesEnd;
        if (!(index ? meshtext::isIndex(line[i]) : meshtext::isReal(line[i])))
            return OffPrecheckWords::tr("expected %1, found %2")
                .arg(index ? OffPrecheckWords::tr("a vertex index")
                           : OffPrecheckWords::tr("a number"),
                     quoted(line[i]));
    }
    return {};
}

// Counts in strayLines the face lines with values after their indices.
QString readFaces(OffLines &lines, const OffKeyword &k, std::int64_t declared, std::string &out,
                  std::size_t &strayLines)
{
    for (quint64 f = 0; f < quint64(declared); ++f) {
        if (!lines.readLine())
            return OffPrecheckWords::tr("the file ends after %1 of %2 faces (truncated?)")
                .arg(f)
                .arg(declared);
        std::size_t indicesEnd = 0;
        if (const QString problem = checkFaceLine(lines.line, f, indicesEnd); !problem.isEmpty())
            return lines.atLine(problem);
        // Values after the indices are a colour, which the reader only takes
        // from the rest of the line under a COFF header; otherwise it would
        // read them as the next face.
        if (lines.line.size() > indicesEnd && !k.colors)
            ++strayLines;
        appendLine(out, lines.line, k.colors ? lines.line.size() : indicesEnd);
    }
    return {};
}

void warnAboutIgnoredText(meshtext::TextTokens &tokens, std::size_t strayLines,
                          MeshFilePrecheck &check)
{
    if (strayLines)
        check.warnings << OffPrecheckWords::tr("ignored the values after the vertex indices on %1 "
                                               "(face colours need a COFF header)")
                              .arg(meshtext::counted(
                                  strayLines, QT_TRANSLATE_NOOP("phonglab::MeshText", "face line"),
                                  QT_TRANSLATE_NOOP("phonglab::MeshText", "face lines")));
    tokens.nextLine();
    if (!tokens.next().empty())
        check.warnings << OffPrecheckWords::tr(
                              "ignored the text after the last face (from line %1)")
                              .arg(tokens.line());
}

} // namespace

bool offHeaderAt(std::string_view head)
{
    meshtext::TextTokens tokens(head, 1, true);
    return parseKeyword(tokens.next()).ok;
}

void precheckOff(const QString &path, MeshFilePrecheck &check)
{
    std::string bytes;
    if (!readWholeFile(path, bytes, check.error))
        return;
    const std::string_view text = bytes;
    meshtext::TextTokens tokens(text, 1, true);
    const OffKeyword k = parseKeyword(tokens.next());
    const std::size_t headerLine = tokens.line();
    if (!k.ok) {
        check.error =
            OffPrecheckWords::tr("not an OFF file (it does not start with an OFF header)");
        return;
    }
    if (k.higherDimension) {
        check.error = OffPrecheckWords::tr("4D and nD OFF files are not supported");
        return;
    }
    const meshtext::TextTokens afterHeader = tokens;
    if (k.rest.empty() && headerLine == 1 && tokens.nextOnLine() == "BINARY")
        return checkBinary(text, k, check);
    check.error = meshtext::binaryDataError(text, QStringLiteral("OFF"));
    if (!check.ok())
        return;

    OffCounts counts;
    tokens = afterHeader; // the token looked at for BINARY may be a count
    if (const QString error = readCounts(tokens, k, headerLine, counts); !error.isEmpty()) {
        check.error = error;
        return;
    }
    // The reader takes the header from line 1 and drops the rest of it.
    bool rewrite = headerLine != 1 || counts.onHeaderLine;
    check.declaredVertices = quint64(counts.values[0]);
    check.declaredFaces = quint64(counts.values[1]);
    if (const QString error = checkDeclaredCounts(text.size(), check); !error.isEmpty()) {
        check.error = error;
        return;
    }

    std::string out = startCleanCopy(k, counts, text.size());
    OffLines lines{tokens, {}};
    if (const QString error = readVertices(lines, k, counts.values[0], out); !error.isEmpty()) {
        check.error = error;
        return;
    }
    std::size_t strayLines = 0;
    if (const QString error = readFaces(lines, k, counts.values[1], out, strayLines);
        !error.isEmpty()) {
        check.error = error;
        return;
    }
    rewrite = rewrite || strayLines;
    warnAboutIgnoredText(tokens, strayLines, check);
    if (rewrite || tokens.sawComment())
        check.rewritten = std::move(out);
}

} // namespace phonglab
