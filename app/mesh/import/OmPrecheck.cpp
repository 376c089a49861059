#include "OmPrecheck.h"

#include "ByteOrder.h"

#include <QCoreApplication>
#include <cstdint>
#include <string_view>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct OmPrecheckWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::OmPrecheck)
};

namespace {

// The numbers in OpenMesh's OMFormat.hh; its reader is the contract here.
enum Entity : unsigned {
    Vertex = 0,
    Mesh = 1,
    Face = 2,
    Edge = 4,
    Halfedge = 6,
    Sentinel = 7
};
enum Type : unsigned {
    Pos = 0,
    Normal = 1,
    Texcoord = 2,
    Status = 3,
    Color = 4,
    Custom = 6,
    Topology = 7
};
constexpr std::uint8_t kVersion2_0 = 2 << 5;
constexpr std::uint8_t kVersion2_1 = (2 << 5) | 1;
constexpr std::size_t kHeaderBytes = 16;

struct OmHeader {
    char mesh = 'T';
    std::uint8_t version = 0;
    quint64 vertices = 0;
    quint64 faces = 0;
    quint64 edges = 0;
};

// A chunk header is 16 bits: reserved, name, entity (3), type (4), signed,
// float, dimension - 1 (3), bits (2).
struct ChunkHeader {
    bool named = false;
    unsigned entity = 0;
    unsigned type = 0;
    bool isFloat = false;
    unsigned dims = 1;
    unsigned bits = 0;
};

ChunkHeader decodeChunkHeader(std::uint32_t v)
{
    ChunkHeader c;
    c.named = (v >> 1) & 1;
    c.entity = (v >> 2) & 7;
    c.type = (v >> 5) & 15;
    c.isFloat = (v >> 10) & 1;
    c.dims = ((v >> 11) & 7) + 1;
    c.bits = (v >> 14) & 3;
    return c;
}

QString describe(const ChunkHeader &c)
{
    static const char *const kEntities[] = {"vertex", "mesh",     "face",     "entity 3",
                                            "edge",   "entity 5", "halfedge", "end"};
    static const char *const kTypes[] = {"positions", "normals", "texture coordinates", "status",
                                         "colours",   "type 5",  "custom property",     "topology"};
    return QStringLiteral("%1 %2").arg(QLatin1String(kEntities[c.entity]),
                                       c.type < 8 ? QLatin1String(kTypes[c.type])
                                                  : QStringLiteral("type %1").arg(c.type));
}

quint64 elementCount(const OmHeader &h, unsigned entity)
{
    switch (entity) {
    case Vertex: return h.vertices;
    case Face: return h.faces;
    case Edge: return h.edges;
    case Halfedge: return 2 * h.edges;
    default: return 1; // mesh
    }
}

// What the reader skips for a chunk it does not interpret (OMFormat's
// chunk_data_size, scalar sizes as odd as it has them).
quint64 skippedSize(const OmHeader &h, const ChunkHeader &c)
{
    const quint64 scalar = c.isFloat ? (1u << c.bits) : (4u << c.bits);
    return elementCount(h, c.entity) * c.dims * scalar;
}

// The outcome of sizing one chunk's data: its byte count, or why the reader
// must not see it.
struct ChunkSize {
    quint64 bytes = 0;
    QString error;
};

ChunkSize sized(quint64 bytes)
{
    return {bytes, {}};
}

ChunkSize wrongDims(const ChunkHeader &c, unsigned expected)
{
    return {0,
            OmPrecheckWords::tr(
                "a %1 chunk with %2 components per element, where the reader expects %3")
                .arg(describe(c))
                .arg(c.dims)
                .arg(expected)};
}

// Vectors of three floats or doubles: positions and normals.
ChunkSize vectorSize(const ChunkHeader &c, quint64 count)
{
    if (c.dims != 3)
        return wrongDims(c, 3);
    if (c.bits > 1)
        return {0,
                OmPrecheckWords::tr("a %1 chunk with a number size the reader does not know")
                    .arg(describe(c))};
    return sized(count * (c.bits == 0 ? 12 : 24));
}

ChunkSize fixedSize(const ChunkHeader &c, unsigned dims, quint64 count, quint64 elementBytes)
{
    if (c.dims != dims)
        return wrongDims(c, dims);
    return sized(count * elementBytes);
}

// A custom property: (from format 2.2 on) its type name, then a 32-bit
// block size and the block. `rest` starts after the chunk header and name.
ChunkSize customSize(const OmHeader &h, std::string_view rest)
{
    quint64 at = 0;
    if (h.version > kVersion2_1) {
        if (rest.empty())
            return {0, OmPrecheckWords::tr("the file ends inside a custom property chunk")};
        at = 1 + static_cast<unsigned char>(rest[0]);
    }
    if (rest.size() < at + 4)
        return {0, OmPrecheckWords::tr("the file ends inside a custom property chunk")};
    return sized(at + 4 + littleEndian(rest, std::size_t(at), 4));
}

// Faces before format 2.0: vertex indices, a 16-bit count first in a
// polygon mesh.
ChunkSize faceIndexSize(const OmHeader &h, const ChunkHeader &c, std::string_view rest)
{
    const quint64 index = 1u << c.bits;
    if (h.mesh != 'P')
        return sized(h.faces * index * (h.mesh == 'T' ? 3 : 4));
    quint64 at = 0;
    for (quint64 f = 0; f < h.faces; ++f) {
        if (rest.size() - at < 2)
            return {0,
                    OmPrecheckWords::tr("the file ends after %1 of %2 faces (truncated?)")
                        .arg(f)
                        .arg(h.faces)};
        at += 2 + index * littleEndian(rest, std::size_t(at), 2);
        if (at > rest.size())
            return {0,
                    OmPrecheckWords::tr("face %1 of %2 runs past the end of the file (truncated?)")
                        .arg(f + 1)
                        .arg(h.faces)};
    }
    return sized(at);
}

// Topology: a halfedge per vertex and per face (from format 2.0 on; vertex
// indices before), three links per halfedge.
ChunkSize topologySize(const OmHeader &h, const ChunkHeader &c, std::string_view rest)
{
    const quint64 index = 1u << c.bits;
    switch (c.entity) {
    case Vertex: return sized(h.vertices * index);
    case Face: return h.version < kVersion2_0 ? faceIndexSize(h, c, rest) : sized(h.faces * index);
    case Halfedge: return sized(h.edges * 6 * index);
    default: return sized(skippedSize(h, c));
    }
}

// The reader's size rules. It asserts the dimensions of the standard types
// (positions and normals 3, texture coordinates 2, colours 3, status 1), on
// more entities in some versions than in others; they are required on all.
// Only the chunks isDrawnChunk() names reach the reader, so a rule for the
// others only has to walk past what a writer puts there.
ChunkSize dataSize(const OmHeader &h, const ChunkHeader &c, std::string_view rest)
{
    if (c.entity != Vertex && c.entity != Mesh && c.entity != Face && c.entity != Edge
        && c.entity != Halfedge)
        return {0,
                OmPrecheckWords::tr("a chunk for an unknown kind of element (%1)").arg(c.entity)};
    const quint64 count = elementCount(h, c.entity);
    switch (c.type) {
    case Pos:
    case Normal: return vectorSize(c, count);
    case Texcoord: return fixedSize(c, 2, count, 8);
    case Color: return fixedSize(c, 3, count, 3);
    case Status: return fixedSize(c, 1, count, 4);
    case Custom: return customSize(h, rest);
    case Topology: return topologySize(h, c, rest);
    default: return sized(skippedSize(h, c));
    }
}

// The chunks PolygonSoupImporter takes from the reader: positions,
// normals and topology. Everything else (texture coordinates, colours,
// status, custom properties) carries nothing PhongLab draws, and the
// reader's handling of it differs between OpenMesh versions.
bool isDrawnChunk(const ChunkHeader &c)
{
    switch (c.entity) {
    case Vertex: return c.type == Pos || c.type == Normal || c.type == Topology;
    case Face:
    case Halfedge: return c.type == Topology;
    default: return false;
    }
}

// Walks the chunks after the header. Returns the error, if any; sets `end`
// to the byte after the end marker and `kept` to the file with only the
// chunks isDrawnChunk() names, when it had others.
QString walkChunks(std::string_view bytes, const OmHeader &h, std::size_t &end, std::string &kept)
{
    std::size_t at = kHeaderBytes;
    std::string drawn(bytes.substr(0, kHeaderBytes));
    bool droppedAny = false;
    for (int chunk = 1;; ++chunk) {
        const std::size_t start = at;
        if (bytes.size() - at < 2)
            return OmPrecheckWords::tr(
                       "the file ends after %1 chunks, before the end marker OpenMesh writes "
                       "(truncated?)")
                .arg(chunk - 1);
        const ChunkHeader c = decodeChunkHeader(littleEndian(bytes, at, 2));
        at += 2;
        if (c.named) {
            if (at >= bytes.size() || bytes.size() - at - 1 < static_cast<unsigned char>(bytes[at]))
                return OmPrecheckWords::tr(
                           "chunk %1 (byte %2): the file ends inside its property name")
                    .arg(chunk)
                    .arg(start);
            at += 1 + static_cast<unsigned char>(bytes[at]);
        }
        if (c.entity == Sentinel) {
            end = at;
            drawn.append(bytes.substr(start, at - start));
            if (droppedAny)
                kept = std::move(drawn);
            return {};
        }
        const ChunkSize size = dataSize(h, c, bytes.substr(at));
        if (!size.error.isEmpty())
            return QStringLiteral("chunk %1 (byte %2): %3").arg(chunk).arg(start).arg(size.error);
        if (size.bytes > bytes.size() - at)
            return OmPrecheckWords::tr(
                       "chunk %1 (byte %2, %3) needs %4 bytes, but only %5 are left "
                       "(truncated or corrupt)")
                .arg(chunk)
                .arg(start)
                .arg(describe(c))
                .arg(size.bytes)
                .arg(bytes.size() - at);
        at += std::size_t(size.bytes);
        if (isDrawnChunk(c))
            drawn.append(bytes.substr(start, at - start));
        else
            droppedAny = true;
    }
}

} // namespace

void precheckOm(const QString &path, MeshFilePrecheck &check)
{
    std::string bytes;
    if (!readWholeFile(path, bytes, check.error))
        return;
    if (bytes.size() < kHeaderBytes) {
        check.error = OmPrecheckWords::tr("the file ends inside the OpenMesh header");
        return;
    }
    OmHeader h;
    h.mesh = bytes[2];
    h.version = static_cast<std::uint8_t>(bytes[3]);
    h.vertices = littleEndian(bytes, 4, 4);
    h.faces = littleEndian(bytes, 8, 4);
    h.edges = littleEndian(bytes, 12, 4);
    check.binary = true;
    check.declaredVertices = h.vertices;
    check.declaredFaces = h.faces;
    // At the least three floats a vertex and a byte a face.
    const quint64 needed = kHeaderBytes + 12 * h.vertices + h.faces;
    if (needed > bytes.size()) {
        check.error =
            OmPrecheckWords::tr(
                "the OpenMesh header declares %1 vertices and %2 faces, which need at least %3 "
                "bytes, but the file has %4 (truncated or corrupt)")
                .arg(h.vertices)
                .arg(h.faces)
                .arg(needed)
                .arg(bytes.size());
        return;
    }
    if (h.faces == 0) {
        check.error = OmPrecheckWords::tr("the OpenMesh file has no faces");
        return;
    }
    std::size_t end = 0;
    check.error = walkChunks(bytes, h, end, check.rewritten);
    if (check.ok() && end < bytes.size())
        check.warnings << OmPrecheckWords::tr("%1 bytes after the end marker were ignored")
                              .arg(bytes.size() - end);
}

} // namespace phonglab
