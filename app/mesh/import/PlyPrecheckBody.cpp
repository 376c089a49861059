// The body of a PLY file checked against its header: a binary one walked
// element by element (list lengths included) without reading it into
// memory, an ascii one validated value by value. Apart from PlyPrecheck.cpp,
// which reads the header and decides whether the body is worth walking.
#include "PlyPrecheckBody.h"

#include "MeshTextTokens.h"

#include <algorithm>
#include <cstring>

namespace phonglab::ply {

using meshtext::quoted;

namespace {

// Sequential reads over the body of a binary PLY with a large buffer, so the
// walk over list lengths costs about as much as reading the file once.
class BodyReader
{
public:
    BodyReader(QFile &file, qint64 offset, qint64 size)
        : m_file(file)
        , m_pos(offset)
        , m_size(size)
    {
    }

    qint64 remaining() const { return m_size - m_pos; }

    bool skip(quint64 n)
    {
        if (n > quint64(remaining()))
            return false;
        m_pos += qint64(n);
        return true;
    }

    bool read(unsigned char *dst, int n)
    {
        if (remaining() < n)
            return false;
        if (m_pos < m_bufStart || m_pos + n > m_bufStart + m_buf.size()) {
            m_file.seek(m_pos);
            m_buf = m_file.read(std::min<qint64>(remaining(), 1 << 20));
            m_bufStart = m_pos;
            if (m_buf.size() < n)
                return false;
        }
        std::memcpy(dst, m_buf.constData() + (m_pos - m_bufStart), std::size_t(n));
        m_pos += n;
        return true;
    }

private:
    QFile &m_file;
    QByteArray m_buf;
    qint64 m_bufStart = 0;
    qint64 m_pos;
    qint64 m_size;
};

std::int64_t decodeInteger(const unsigned char *b, const PlyType &t, bool bigEndian)
{
    std::uint32_t u = 0;
    for (int i = 0; i < t.size; ++i)
        u |= std::uint32_t(b[bigEndian ? t.size - 1 - i : i]) << (8 * i);
    if (!t.isSigned)
        return u;
    const int bits = 8 * t.size;
    return bits == 32
        ? std::int64_t(std::int32_t(u))
        : (std::int64_t(u) ^ (std::int64_t(1) << (bits - 1))) - (std::int64_t(1) << (bits - 1));
}

QString truncatedAt(const PlyElement &e, quint64 index)
{
    return PlyPrecheckWords::tr("the file ends inside %1 %2 of %3 (truncated?)")
        .arg(QString::fromStdString(e.name))
        .arg(index + 1)
        .arg(e.count);
}

bool valueFits(std::string_view t, const PlyType &type)
{
    return type.integer ? meshtext::isIndex(t) : meshtext::isReal(t);
}

} // namespace

void walkBinary(QFile &file, const PlyHeader &h, MeshFilePrecheck &check)
{
    BodyReader body(file, h.bodyOffset, check.fileSize);
    const bool bigEndian = h.format == PlyHeader::BigEndian;
    for (const PlyElement &e : h.elements) {
        quint64 stride = 0;
        bool hasList = false;
        for (const PlyProperty &p : e.properties) {
            hasList = hasList || p.isList;
            stride += quint64(p.type.size);
        }
        if (!hasList) {
            if (!body.skip(e.count * stride)) {
                check.error =
                    truncatedAt(e, quint64(body.remaining()) / std::max<quint64>(stride, 1));
                return;
            }
            continue;
        }
        for (quint64 i = 0; i < e.count; ++i) {
            for (const PlyProperty &p : e.properties) {
                if (!p.isList) {
                    if (!body.skip(quint64(p.type.size))) {
                        check.error = truncatedAt(e, i);
                        return;
                    }
                    continue;
                }
                unsigned char raw[4];
                if (!body.read(raw, p.countType.size)) {
                    check.error = truncatedAt(e, i);
                    return;
                }
                const std::int64_t n = decodeInteger(raw, p.countType, bigEndian);
                if (n < 0) {
                    check.error = PlyPrecheckWords::tr("%1 %2 has a negative list length")
                                      .arg(QString::fromStdString(e.name))
                                      .arg(i + 1);
                    return;
                }
                if (!body.skip(quint64(n) * quint64(p.type.size))) {
                    check.error = truncatedAt(e, i);
                    return;
                }
            }
        }
    }
    if (body.remaining() > 0)
        check.warnings << PlyPrecheckWords::tr("ignored %1 after the last element")
                              .arg(meshtext::counted(
                                  quint64(body.remaining()),
                                  QT_TRANSLATE_NOOP("phonglab::MeshText", "byte"),
                                  QT_TRANSLATE_NOOP("phonglab::MeshText", "bytes")));
}

void validateAscii(std::string_view body, const PlyHeader &h, MeshFilePrecheck &check)
{
    meshtext::TextTokens tokens(body, h.bodyLine);
    for (const PlyElement &e : h.elements) {
        const QString name = QString::fromStdString(e.name);
        for (quint64 i = 0; i < e.count; ++i) {
            for (const PlyProperty &p : e.properties) {
                std::string_view t = tokens.next();
                if (t.empty()) {
                    check.error = truncatedAt(e, i);
                    return;
                }
                auto bad = [&](const QString &what) {
                    check.error = QStringLiteral("line %1: expected %2 for '%3' of %4 %5, found %6")
                                      .arg(tokens.line())
                                      .arg(what, QString::fromStdString(p.name), name)
                                      .arg(i + 1)
                                      .arg(quoted(t));
                };
                if (!p.isList) {
                    if (!valueFits(t, p.type))
                        return bad(p.type.integer ? PlyPrecheckWords::tr("an integer")
                                                  : QStringLiteral("a number"));
                    continue;
                }
                std::int64_t n = -1;
                if (!meshtext::parseInteger(t, n) || n < 0 || quint64(n) > body.size() / 2)
                    return bad(PlyPrecheckWords::tr("a list length"));
                for (std::int64_t k = 0; k < n; ++k) {
                    t = tokens.next();
                    if (t.empty()) {
                        check.error = truncatedAt(e, i);
                        return;
                    }
                    if (!valueFits(t, p.type))
                        return bad(p.type.integer ? PlyPrecheckWords::tr("an integer")
                                                  : QStringLiteral("a number"));
                }
            }
        }
    }
    if (!tokens.next().empty())
        check.warnings << PlyPrecheckWords::tr(
                              "ignored the text after the last element (from line %1)")
                              .arg(tokens.line());
}

} // namespace phonglab::ply
