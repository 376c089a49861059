#include "CapturedVertices.h"

#include "CaptureBounds.h"

#include <algorithm>
#include <cstring>

namespace phonglab {

namespace {

template <typename T> double read(const char *at)
{
    T value;
    std::memcpy(&value, at, sizeof value);
    return double(value);
}

double component(const char *at, unsigned type, bool normalized)
{
    switch (type) {
    case 0x1406: return read<float>(at);
    case 0x1400: return normalized ? std::max(-1.0, read<qint8>(at) / 127.0) : read<qint8>(at);
    case 0x1401: return normalized ? read<quint8>(at) / 255.0 : read<quint8>(at);
    case 0x1402: return normalized ? std::max(-1.0, read<qint16>(at) / 32767.0) : read<qint16>(at);
    case 0x1403: return normalized ? read<quint16>(at) / 65535.0 : read<quint16>(at);
    case 0x1404:
        return normalized ? std::max(-1.0, read<qint32>(at) / 2147483647.0) : read<qint32>(at);
    case 0x1405: return normalized ? read<quint32>(at) / 4294967295.0 : read<quint32>(at);
    default: return 0;
    }
}

template <typename T>
void appendIndices(const QByteArray &bytes, qint64 offset, int count, T restart, bool skip,
                   std::vector<qint64> *out)
{
    for (int i = 0; i < count; ++i) {
        T index;
        std::memcpy(&index, bytes.constData() + offset + qint64(i) * qint64(sizeof(T)), sizeof(T));
        if (!skip || index != restart)
            out->push_back(qint64(index));
    }
}

} // namespace

std::optional<std::vector<qint64>> drawnVertices(const PageCapture &capture, const CapturedOp &draw)
{
    if (!drawOutOfBounds(capture, draw).isEmpty())
        return std::nullopt;
    std::vector<qint64> out;
    if (draw.count <= 0)
        return out;
    out.reserve(std::size_t(draw.count));
    if (!draw.indexed()) {
        for (int i = 0; i < draw.count; ++i)
            out.push_back(qint64(draw.first) + i);
        return out;
    }
    const QByteArray &bytes = capture.buffer(draw.indices)->bytes;
    const bool restart = capture.webgl == 2;
    switch (componentBytes(draw.indexType)) {
    case 1: appendIndices<quint8>(bytes, draw.offset, draw.count, 0xFF, restart, &out); break;
    case 2: appendIndices<quint16>(bytes, draw.offset, draw.count, 0xFFFF, restart, &out); break;
    default: appendIndices<quint32>(bytes, draw.offset, draw.count, 0xFFFFFFFFu, restart, &out);
    }
    return out;
}

std::vector<glm::dvec4> attributeValues(const PageCapture &capture,
                                        const CapturedAttribute &attribute,
                                        const std::vector<qint64> &vertices)
{
    const glm::dvec4 constant(attribute.value[0], attribute.value[1], attribute.value[2],
                              attribute.value[3]);
    std::vector<glm::dvec4> out(vertices.size(), constant);
    const CapturedBuffer *buffer = capture.buffer(attribute.buffer);
    const int bytes = componentBytes(attribute.component);
    if (!attribute.enabled || !buffer || bytes == 0)
        return out;
    const qint64 stride = attributeStride(attribute);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const qint64 base = attribute.offset + vertices[i] * stride;
        if (base < 0 || base + qint64(attribute.size) * bytes > buffer->bytes.size())
            continue;
        glm::dvec4 v(0, 0, 0, 1);
        for (int c = 0; c < attribute.size; ++c)
            v[c] = component(buffer->bytes.constData() + base + c * bytes, attribute.component,
                             attribute.normalized);
        out[i] = v;
    }
    return out;
}

} // namespace phonglab
