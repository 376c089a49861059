#include "CaptureBounds.h"

#include <QCoreApplication>

#include <cstring>

namespace phonglab {

struct CaptureBoundsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::CaptureBounds)
};

namespace {

constexpr qint64 kMaxVertices = 64 * 1024 * 1024;
constexpr int kMaxStride = 255;

template <typename T>
qint64 largestIndex(const QByteArray &bytes, qint64 offset, qint64 count, T restart)
{
    qint64 largest = -1;
    for (qint64 i = 0; i < count; ++i) {
        T index;
        std::memcpy(&index, bytes.constData() + offset + i * qint64(sizeof(T)), sizeof(T));
        if (index != restart)
            largest = std::max<qint64>(largest, qint64(index));
    }
    return largest;
}

} // namespace

int componentBytes(unsigned glType)
{
    switch (glType) {
    case 0x1400: // BYTE
    case 0x1401: // UNSIGNED_BYTE
        return 1;
    case 0x1402: // SHORT
    case 0x1403: // UNSIGNED_SHORT
    case 0x140B: // HALF_FLOAT
        return 2;
    case 0x1404: // INT
    case 0x1405: // UNSIGNED_INT
    case 0x1406: // FLOAT
        return 4;
    default: return 0;
    }
}

qint64 attributeStride(const CapturedAttribute &attribute)
{
    return attribute.stride > 0 ? attribute.stride
                                : qint64(attribute.size) * componentBytes(attribute.component);
}

std::optional<qint64> largestVertex(const PageCapture &capture, const CapturedOp &draw,
                                    QString *problem)
{
    if (draw.count <= 0)
        return -1;
    if (!draw.indexed()) {
        if (draw.first < 0)
            return (*problem = CaptureBoundsWords::tr("a negative first vertex"), std::nullopt);
        return qint64(draw.first) + draw.count - 1;
    }
    const CapturedBuffer *indices = capture.buffer(draw.indices);
    const int bytes = componentBytes(draw.indexType);
    // Each side apart: a sum of hostile numbers must not wrap past the check.
    if (!indices || bytes == 0 || draw.offset < 0 || draw.offset % bytes != 0
        || draw.offset > indices->bytes.size() || draw.count > kMaxVertices
        || qint64(draw.count) * bytes > indices->bytes.size() - draw.offset)
        return (
            *problem =
                CaptureBoundsWords::tr("the index buffer does not hold %1 indices").arg(draw.count),
            std::nullopt);
    // WebGL 2 always restarts a primitive at the largest index; WebGL 1 has no restart.
    const bool restart = capture.webgl == 2;
    switch (bytes) {
    case 1:
        return largestIndex<quint8>(indices->bytes, draw.offset, draw.count,
                                    restart ? 0xFF : quint8(0));
    case 2:
        return largestIndex<quint16>(indices->bytes, draw.offset, draw.count,
                                     restart ? 0xFFFF : quint16(0));
    default:
        return largestIndex<quint32>(indices->bytes, draw.offset, draw.count,
                                     restart ? 0xFFFFFFFFu : 0u);
    }
}

QString drawOutOfBounds(const PageCapture &capture, const CapturedOp &draw)
{
    QString problem;
    const std::optional<qint64> last = largestVertex(capture, draw, &problem);
    if (!last)
        return problem;
    if (*last >= kMaxVertices || draw.instances < 0 || draw.instances > kMaxVertices)
        return CaptureBoundsWords::tr("more vertices than PhongLab draws again");
    for (const CapturedAttribute &a : draw.attributes) {
        if (!a.enabled)
            continue;
        const int bytes = componentBytes(a.component);
        // WebGL allows strides up to 255 bytes; anything else is no capture of it.
        if (bytes == 0 || a.size < 1 || a.size > 4 || a.offset < 0 || a.stride < 0
            || a.stride > kMaxStride || a.divisor < 0)
            return CaptureBoundsWords::tr("attribute %1 has a layout PhongLab does not draw")
                .arg(a.name);
        const CapturedBuffer *buffer = capture.buffer(a.buffer);
        if (!buffer)
            return CaptureBoundsWords::tr("attribute %1 reads no buffer").arg(a.name);
        const qint64 reads = a.divisor > 0 ? (draw.instances - 1) / a.divisor : *last;
        if (reads < 0)
            continue;
        if (a.offset > buffer->bytes.size())
            return CaptureBoundsWords::tr("attribute %1 starts past its buffer").arg(a.name);
        // reads < 2^26 and the stride <= 255: no product here wraps.
        const qint64 end = a.offset + reads * attributeStride(a) + qint64(a.size) * bytes;
        if (end > buffer->bytes.size())
            return CaptureBoundsWords::tr("attribute %1 reads %2 bytes of a buffer of %3")
                .arg(a.name)
                .arg(end)
                .arg(buffer->bytes.size());
    }
    return {};
}

} // namespace phonglab
