#include "ObjReader.h"

#include "MeshFilePrecheck.h"
#include "MeshTextTokens.h"
#include "ObjReaderNumbers.h"

#include <QCoreApplication>
#include <atomic>
#include <cstring>
#include <future>
#include <limits>
#include <string>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ObjReaderWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ObjReader)
};

namespace {

constexpr std::uint32_t kBadIndex = 0xffffffffu;
// A normal reference that cannot exist, told apart from "no normal" until
// the end, where it is counted and becomes kNoNormal.
constexpr std::uint32_t kBadNormal = 0xfffffffeu;
constexpr std::size_t kProgressBytes = 4 << 20;
// Below this a second parsing thread costs more than it saves.
constexpr std::size_t kParallelBytes = 8 << 20;

using objtext::isBlank;
using objtext::parseFloat;
using objtext::parseInt;
using objtext::skipBlanks;

// OBJ indices are 1-based; negative ones count back from the latest element.
inline std::uint32_t resolve(std::int64_t i, std::size_t count, std::uint32_t bad)
{
    if (i > 0)
        return i < std::int64_t(kBadNormal) ? std::uint32_t(i - 1) : bad;
    if (i < 0 && -i <= std::int64_t(count))
        return std::uint32_t(std::int64_t(count) + i);
    return bad;
}

bool keywordIn(std::string_view k, std::initializer_list<std::string_view> list)
{
    for (std::string_view s : list)
        if (k == s)
            return true;
    return false;
}

// Parses a run of whole lines; one parser can go on where another left off
// (append()), so the two halves of a large file are parsed side by side.
class ObjParser
{
public:
    // The lines of [p, end), numbered on from those parsed before. False
    // when progress() said stop or `stop` was set.
    bool parseLines(const char *p, const char *end, const char *textBegin, std::size_t textSize,
                    const std::function<bool(double)> &progress, const std::atomic<bool> *stop);
    // Lines that come after this parser's, parsed on their own: correct
    // only when they hold no relative index (those count back from the
    // vertices before them, which that parser did not see).
    void append(ObjParser &&later);
    bool sawRelativeIndex() const { return m_relativeIndex; }
    void finish(MeshReadResult &result, bool endsInNewline);

private:
    bool parseLine(const char *p, const char *e);
    bool parseVec3(const char *p, const char *e, std::vector<glm::vec3> &out);
    bool parseFace(const char *p, const char *e);

    PolygonMesh m_mesh;
    bool m_anyCornerNormal = false;
    bool m_relativeIndex = false;
    std::size_t m_lineNo = 0;
    bool m_lastLineBad = false;
    std::size_t m_badLines = 0;
    std::size_t m_firstBadLine = 0;
    std::string m_firstBadText;
    std::size_t m_freeform = 0;
};

bool ObjParser::parseVec3(const char *p, const char *e, std::vector<glm::vec3> &out)
{
    float v[3];
    for (float &c : v) {
        p = parseFloat(skipBlanks(p, e), e, c);
        if (!p) {
            // Keep the index: later faces count on it.
            out.emplace_back(std::numeric_limits<float>::quiet_NaN());
            return false;
        }
    }
    out.emplace_back(v[0], v[1], v[2]);
    return true;
}

bool ObjParser::parseFace(const char *p, const char *e)
{
    const std::size_t first = m_mesh.cornerPosition.size();
    const std::size_t positions = m_mesh.positions.size();
    const std::size_t normals = m_mesh.normals.size();
    for (p = skipBlanks(p, e); p < e && *p != '#'; p = skipBlanks(p, e)) {
        std::int64_t v = 0;
        const char *q = parseInt(p, e, v);
        std::uint32_t normal = PolygonMesh::kNoNormal;
        if (q && q < e && *q == '/') {
            ++q;
            std::int64_t unused = 0;
            if (q < e && *q != '/')
                q = parseInt(q, e, unused);
            if (q && q < e && *q == '/') {
                std::int64_t n = 0;
                q = parseInt(q + 1, e, n);
                normal = resolve(n, normals, kBadNormal);
                m_relativeIndex = m_relativeIndex || n < 0;
                m_anyCornerNormal = true;
            }
        }
        if (!q || (q < e && !isBlank(*q))) {
            m_mesh.cornerPosition.resize(first);
            m_mesh.cornerNormal.resize(first);
            return false;
        }
        m_relativeIndex = m_relativeIndex || v < 0;
        m_mesh.cornerPosition.push_back(resolve(v, positions, kBadIndex));
        m_mesh.cornerNormal.push_back(normal);
        p = q;
    }
    m_mesh.faceStart.push_back(std::uint32_t(m_mesh.cornerPosition.size()));
    return true;
}

bool ObjParser::parseLine(const char *p, const char *e)
{
    p = skipBlanks(p, e);
    if (p == e || *p == '#')
        return true;
    const char *k = p;
    while (p < e && !isBlank(*p))
        ++p;
    const std::string_view key(k, std::size_t(p - k));
    if (key == "v")
        return parseVec3(p, e, m_mesh.positions);
    if (key == "f" || key == "fo")
        return parseFace(p, e);
    if (key == "vn")
        return parseVec3(p, e, m_mesh.normals);
    if (keywordIn(key,
                  {"vt", "o", "g", "s", "usemtl", "mtllib", "l", "p", "mg", "lod", "bevel",
                   "c_interp", "d_interp", "usemap", "maplib", "shadow_obj", "trace_obj", "ctech",
                   "stech"}))
        return true;
    if (keywordIn(key,
                  {"vp", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim",
                   "hole", "scrv", "sp", "end", "con"})) {
        ++m_freeform;
        return true;
    }
    return false;
}

bool ObjParser::parseLines(const char *p, const char *end, const char *textBegin,
                           std::size_t textSize, const std::function<bool(double)> &progress,
                           const std::atomic<bool> *stop)
{
    const char *nextReport = p + kProgressBytes;
    std::string joined;
    while (p < end) {
        const char *nl = static_cast<const char *>(std::memchr(p, '\n', std::size_t(end - p)));
        const char *next = nl ? nl + 1 : end;
        const char *e = nl ? nl : end;
        if (e > p && e[-1] == '\r')
            --e;
        const std::size_t firstLine = ++m_lineNo;
        const char *lineBegin = p;
        const char *lineEnd = e;
        if (e > p && e[-1] == '\\') {
            // A continued line: join it with the following ones.
            joined.assign(p, e - 1);
            while (next < end && lineEnd > lineBegin && lineEnd[-1] == '\\') {
                nl = static_cast<const char *>(std::memchr(next, '\n', std::size_t(end - next)));
                lineBegin = next;
                lineEnd = nl ? nl : end;
                if (lineEnd > lineBegin && lineEnd[-1] == '\r')
                    --lineEnd;
                ++m_lineNo;
                joined += ' ';
                const bool continues = lineEnd > lineBegin && lineEnd[-1] == '\\';
                joined.append(lineBegin, continues ? lineEnd - 1 : lineEnd);
                next = nl ? nl + 1 : end;
            }
            lineBegin = joined.data();
            lineEnd = joined.data() + joined.size();
        }
        m_lastLineBad = !parseLine(lineBegin, lineEnd);
        if (m_lastLineBad && m_badLines++ == 0) {
            m_firstBadLine = firstLine;
            m_firstBadText.assign(lineBegin,
                                  std::min<std::size_t>(std::size_t(lineEnd - lineBegin), 60));
        }
        p = next;
        if (p >= nextReport) {
            nextReport = p + kProgressBytes;
            if (progress && !progress(double(p - textBegin) / double(textSize)))
                return false;
            if (stop && stop->load(std::memory_order_relaxed))
                return false;
        }
    }
    return true;
}

template <typename T> void appendAll(std::vector<T> &to, const std::vector<T> &from)
{
    to.reserve(to.size() + from.size());
    to.insert(to.end(), from.begin(), from.end());
}

void ObjParser::append(ObjParser &&later)
{
    const std::uint32_t corners = std::uint32_t(m_mesh.cornerPosition.size());
    appendAll(m_mesh.positions, later.m_mesh.positions);
    appendAll(m_mesh.normals, later.m_mesh.normals);
    appendAll(m_mesh.cornerPosition, later.m_mesh.cornerPosition);
    appendAll(m_mesh.cornerNormal, later.m_mesh.cornerNormal);
    m_mesh.faceStart.reserve(m_mesh.faceStart.size() + later.m_mesh.faceCount());
    for (std::size_t f = 1; f < later.m_mesh.faceStart.size(); ++f)
        m_mesh.faceStart.push_back(corners + later.m_mesh.faceStart[f]);
    m_anyCornerNormal = m_anyCornerNormal || later.m_anyCornerNormal;
    m_relativeIndex = m_relativeIndex || later.m_relativeIndex;
    if (m_badLines == 0 && later.m_badLines != 0) {
        m_firstBadLine = m_lineNo + later.m_firstBadLine;
        m_firstBadText = std::move(later.m_firstBadText);
    }
    m_badLines += later.m_badLines;
    m_freeform += later.m_freeform;
    if (later.m_lineNo != 0)
        m_lastLineBad = later.m_lastLineBad;
    m_lineNo += later.m_lineNo;
}

void ObjParser::finish(MeshReadResult &result, bool endsInNewline)
{
    if (m_mesh.faceCount() == 0) {
        result.error = m_mesh.positions.empty()
            ? ObjReaderWords::tr("no vertices or faces found (not an OBJ file?)")
            : ObjReaderWords::tr("the file has vertices but no faces");
        return;
    }
    std::size_t missingNormals = 0;
    if (!m_anyCornerNormal) {
        m_mesh.cornerNormal.clear();
        m_mesh.cornerNormal.shrink_to_fit();
    } else {
        for (std::uint32_t &n : m_mesh.cornerNormal) {
            if (n != PolygonMesh::kNoNormal && n >= m_mesh.normals.size()) {
                n = PolygonMesh::kNoNormal;
                ++missingNormals;
            }
        }
    }
    if (m_badLines)
        result.warnings << ObjReaderWords::tr("skipped %1 (first at line %2: \"%3\")")
                               .arg(meshtext::counted(
                                   m_badLines,
                                   QT_TRANSLATE_NOOP("phonglab::MeshText", "unreadable line"),
                                   QT_TRANSLATE_NOOP("phonglab::MeshText", "unreadable lines")))
                               .arg(m_firstBadLine)
                               .arg(QString::fromUtf8(m_firstBadText));
    if (m_lastLineBad && !endsInNewline)
        result.warnings << ObjReaderWords::tr(
            "the last line is incomplete (the file looks truncated)");
    if (m_freeform)
        result.warnings << ObjReaderWords::tr("ignored %1 (only polygons are read)")
                               .arg(meshtext::counted(
                                   m_freeform,
                                   QT_TRANSLATE_NOOP("phonglab::MeshText",
                                                     "free-form curve or surface statement"),
                                   QT_TRANSLATE_NOOP("phonglab::MeshText",
                                                     "free-form curve and surface statements")));
    if (missingNormals)
        result.warnings << ObjReaderWords::tr(
                               "%1 to normals the file does not have; they get computed normals")
                               .arg(meshtext::counted(
                                   missingNormals,
                                   QT_TRANSLATE_NOOP("phonglab::MeshText", "face corner refers"),
                                   QT_TRANSLATE_NOOP("phonglab::MeshText", "face corners refer")));
    result.mesh = std::move(m_mesh);
}

} // namespace

namespace {

// Where a large text can be cut in two: the start of a line near the middle
// that does not continue the line before (a trailing `\`). Null for a text
// too small to be worth a second thread.
const char *splitPoint(const char *begin, const char *end)
{
    if (std::size_t(end - begin) < kParallelBytes)
        return nullptr;
    for (const char *p = begin + (end - begin) / 2; p < end;) {
        const char *nl = static_cast<const char *>(std::memchr(p, '\n', std::size_t(end - p)));
        if (!nl || nl + 1 >= end)
            return nullptr;
        const char *e = nl > begin && nl[-1] == '\r' ? nl - 1 : nl;
        if (e == begin || e[-1] != '\\')
            return nl + 1;
        p = nl + 1;
    }
    return nullptr;
}

} // namespace

// A large file's second half is parsed on a second thread while this one
// parses the first, then appended. Relative indices in the second half need
// the vertex count before them: then it is parsed again after the first,
// as one thread would have.
MeshReadResult parseObj(std::string_view text, const std::function<bool(double)> &progress)
{
    MeshReadResult result;
    const char *const begin = text.data();
    const char *const end = begin + text.size();
    // Some Windows tools start text files with a UTF-8 byte order mark.
    const char *const start = text.substr(0, 3) == "\xEF\xBB\xBF" ? begin + 3 : begin;
    const char *const split = splitPoint(start, end);
    ObjParser parser;
    bool done = false;
    if (!split) {
        done = parser.parseLines(start, end, begin, text.size(), progress, nullptr);
    } else {
        std::atomic<bool> stop = false;
        ObjParser later;
        std::future<bool> laterDone = std::async(std::launch::async, [&] {
            return later.parseLines(split, end, begin, text.size(), {}, &stop);
        });
        done = parser.parseLines(start, split, begin, text.size(), progress, nullptr);
        stop = !done;
        laterDone.get();
        if (done && later.sawRelativeIndex())
            done = parser.parseLines(split, end, begin, text.size(), progress, nullptr);
        else if (done)
            parser.append(std::move(later));
        // The second half reported nothing: its end is a chance to cancel.
        done = done && (!progress || progress(1.0));
    }
    if (!done) {
        result.error = QStringLiteral("cancelled");
        return result;
    }
    parser.finish(result, !text.empty() && text.back() == '\n');
    return result;
}

MeshReadResult readObjFile(const QString &path, const std::function<bool(double)> &progress)
{
    // Reading is cheap next to parsing: it gets the first tenth of progress.
    std::string text;
    MeshReadResult result;
    auto readProgress = [&](double f) { return !progress || progress(0.1 * f); };
    if (!readWholeFile(path, text, result.error, readProgress))
        return result;
    auto parseProgress = [&](double f) { return !progress || progress(0.1 + 0.9 * f); };
    return parseObj(text, parseProgress);
}

} // namespace phonglab
