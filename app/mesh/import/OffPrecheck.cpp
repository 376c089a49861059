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

    // The reader takes the header from line 1 and drops the rest of it.
    bool rewrite = headerLine != 1;
    std::int64_t counts[3] = {};
    tokens = afterHeader; // the token looked at for BINARY may be a count
    for (int i = 0; i < 3; ++i) {
        const std::string_view t = (i == 0 && !k.rest.empty()) ? k.rest : tokens.next();
        if (!meshtext::parseInteger(t, counts[i]) || counts[i] < 0 || counts[i] > UINT32_MAX) {
            check.error =
                OffPrecheckWords::tr("line %1: expected the vertex, face and edge counts, found %2")
                    .arg(tokens.line())
                    .arg(quoted(t));
            return;
        }
        rewrite = rewrite || tokens.line() == headerLine;
    }
    if (!tokens.lineIsEmpty()) {
        check.error =
            OffPrecheckWords::tr("line %1: unexpected text after the counts").arg(tokens.line());
        return;
    }
    check.declaredVertices = quint64(counts[0]);
    check.declaredFaces = quint64(counts[1]);
    // At the least "0 0 0\n" a vertex and "3 0 0 0\n" a face.
    const quint64 needed = 6 * check.declaredVertices + 8 * check.declaredFaces;
    if (needed > text.size()) {
        check.error =
            OffPrecheckWords::tr(
                "the OFF header declares %1 vertices and %2 faces, which need at least %3 "
                "bytes, but the file has %4 (truncated or corrupt)")
                .arg(check.declaredVertices)
                .arg(check.declaredFaces)
                .arg(needed)
                .arg(text.size());
        return;
    }
    if (check.declaredFaces == 0) {
        check.error = OffPrecheckWords::tr("the OFF file has no faces");
        return;
    }

    std::string out;
    out.reserve(text.size());
    out.append(k.keyword).append("\n");
    out.append(std::to_string(counts[0]))
        .append(" ")
        .append(std::to_string(counts[1]))
        .append(" ")
        .append(std::to_string(counts[2]))
        .append("\n");

    std::vector<std::string_view> line;
    auto readLine = [&] {
        tokens.nextLine();
        while (!tokens.atEnd() && tokens.lineIsEmpty())
            tokens.nextLine();
        line.clear();
        for (std::string_view t = tokens.nextOnLine(); !t.empty(); t = tokens.nextOnLine())
            line.push_back(t);
        return !line.empty();
    };
    auto fail = [&](const QString &message) {
        check.error = QStringLiteral("line %1: %2").arg(tokens.line()).arg(message);
    };

    const std::size_t vertexNumbers = k.normals ? 6 : 3;
    for (quint64 v = 0; v < check.declaredVertices; ++v) {
        if (!readLine()) {
            check.error = OffPrecheckWords::tr("the file ends after %1 of %2 vertices (truncated?)")
                              .arg(v)
                              .arg(counts[0]);
            return;
        }
        if (line.size() < vertexNumbers)
            return fail(OffPrecheckWords::tr("vertex %1 needs %2 numbers, found %3")
                            .arg(v + 1)
                            .arg(vertexNumbers)
                            .arg(line.size()));
        for (std::string_view t : line)
            if (!meshtext::isReal(t))
                return fail(OffPrecheckWords::tr("expected a number, found %1").arg(quoted(t)));
        appendLine(out, line, line.size());
    }

    std::size_t strayLines = 0;
    for (quint64 f = 0; f < check.declaredFaces; ++f) {
        if (!readLine()) {
            check.error = OffPrecheckWords::tr("the file ends after %1 of %2 faces (truncated?)")
                              .arg(f)
                              .arg(counts[1]);
            return;
        }
        std::int64_t corners = -1;
        if (!meshtext::parseInteger(line[0], corners) || corners < 0)
            return fail(OffPrecheckWords::tr("expected the corner count of face %1, found %2")
                            .arg(f + 1)
                            .arg(quoted(line[0])));
        if (std::size_t(corners) > line.size() - 1)
            return fail(OffPrecheckWords::tr("face %1 has %2 corners but only %3 indices")
                            .arg(f + 1)
                            .arg(corners)
                            .arg(line.size() - 1));
        const std::size_t indicesEnd = std::size_t(corners) + 1;
        for (std::size_t i = 1; i < line.size(); ++i) {
            const bool index = i < indicesEnd;
            if (!(index ? meshtext::isIndex(line[i]) : meshtext::isReal(line[i])))
                return fail(OffPrecheckWords::tr("expected %1, found %2")
                                .arg(index ? OffPrecheckWords::tr("a vertex index")
                                           : OffPrecheckWords::tr("a number"),
                                     quoted(line[i])));
        }
        // Values after the indices are a colour, which the reader only takes
        // from the rest of the line under a COFF header; otherwise it would
        // read them as the next face.
        if (line.size() > indicesEnd && !k.colors) {
            ++strayLines;
            rewrite = true;
        }
        appendLine(out, line, k.colors ? line.size() : indicesEnd);
    }
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
    if (rewrite || tokens.sawComment())
        check.rewritten = std::move(out);
}

} // namespace phonglab
