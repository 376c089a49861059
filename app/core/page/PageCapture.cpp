#include "PageCapture.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace phonglab {

struct PageCaptureWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PageCapture)
};

namespace {

// A JSON number as a byte count or offset: anything a capture of a real
// page can hold (a buffer is at most 2 GiB), -1 for the rest, so that a
// hostile file cannot hand a bounds check a number near 2^63.
qint64 byteNumber(const QJsonValue &value)
{
    const double v = value.toDouble(0);
    if (!(v >= 0 && v <= double(qint64(1) << 31)) || v != std::floor(v))
        return -1;
    return qint64(v);
}

QString key(const char *name)
{
    return QString::fromLatin1(name);
}

CallStack readStack(const QJsonValue &value)
{
    CallStack stack;
    for (const QJsonValue &frame : value.toArray()) {
        const QJsonObject o = frame.toObject();
        stack.push_back({o.value(key("file")).toString(), o.value(key("line")).toInt(),
                         o.value(key("column")).toInt(), o.value(key("function")).toString()});
    }
    return stack;
}

template <typename T, std::size_t N>
std::array<T, N> readArray(const QJsonValue &value, std::array<T, N> fallback)
{
    const QJsonArray a = value.toArray();
    if (a.size() != qsizetype(N))
        return fallback;
    std::array<T, N> out{};
    for (std::size_t i = 0; i < N; ++i)
        out[i] =
            a[qsizetype(i)].isBool() ? T(a[qsizetype(i)].toBool()) : T(a[qsizetype(i)].toDouble());
    return out;
}

CapturedState readState(const QJsonObject &o)
{
    CapturedState s;
    s.viewport = readArray(o.value(key("viewport")), s.viewport);
    s.depthTest = o.value(key("depthTest")).toBool();
    s.depthFunc = unsigned(o.value(key("depthFunc")).toInt(int(s.depthFunc)));
    s.depthMask = o.value(key("depthMask")).toBool(true);
    s.cullFace = o.value(key("cullFace")).toBool();
    s.cullMode = unsigned(o.value(key("cullMode")).toInt(int(s.cullMode)));
    s.frontFace = unsigned(o.value(key("frontFace")).toInt(int(s.frontFace)));
    s.blend = o.value(key("blend")).toBool();
    s.blendFunc = readArray(o.value(key("blendFunc")), s.blendFunc);
    s.colorMask = readArray(o.value(key("colorMask")), s.colorMask);
    s.scissorTest = o.value(key("scissorTest")).toBool();
    s.scissor = readArray(o.value(key("scissor")), s.scissor);
    return s;
}

CapturedUniform readUniform(const QJsonObject &o)
{
    CapturedUniform u;
    u.name = o.value(key("name")).toString();
    u.glType = unsigned(o.value(key("type")).toInt());
    u.size = std::max(1, o.value(key("size")).toInt(1));
    u.isArray = o.value(key("array")).toBool();
    for (const QJsonValue &element : o.value(key("values")).toArray()) {
        std::vector<double> v;
        for (const QJsonValue &x : element.toArray())
            v.push_back(x.toDouble());
        u.values.push_back(std::move(v));
    }
    u.setAt = readStack(o.value(key("set_at")));
    return u;
}

CapturedAttribute readAttribute(const QJsonObject &o)
{
    CapturedAttribute a;
    a.name = o.value(key("name")).toString();
    a.glType = unsigned(o.value(key("type")).toInt());
    a.location = o.value(key("location")).toInt(-1);
    a.enabled = o.value(key("enabled")).toBool();
    a.buffer = o.value(key("buffer")).toString();
    a.size = o.value(key("size")).toInt(4);
    a.component = unsigned(o.value(key("component")).toInt());
    a.normalized = o.value(key("normalized")).toBool();
    a.stride = o.value(key("stride")).toInt();
    a.offset = byteNumber(o.value(key("offset")));
    a.integer = o.value(key("integer")).toBool();
    a.divisor = o.value(key("divisor")).toInt();
    const QJsonArray value = o.value(key("value")).toArray();
    for (qsizetype i = 0; i < std::min<qsizetype>(4, value.size()); ++i)
        a.value[std::size_t(i)] = value[i].toDouble();
    return a;
}

CapturedOp readOp(const QJsonObject &o)
{
    CapturedOp op;
    op.kind = o.value(key("op")).toString() == key("clear") ? CapturedOp::Kind::Clear
                                                            : CapturedOp::Kind::Draw;
    op.state = readState(o.value(key("state")).toObject());
    op.clearMask = unsigned(o.value(key("mask")).toInt());
    op.clearColor = readArray(o.value(key("color")), op.clearColor);
    op.clearDepth = o.value(key("depth")).toDouble(1);
    op.drawKind = o.value(key("kind")).toString();
    op.program = o.value(key("program")).toInt();
    op.mode = unsigned(o.value(key("mode")).toInt(4));
    op.first = o.value(key("first")).toInt();
    op.count = o.value(key("count")).toInt();
    op.indexType = unsigned(o.value(key("indexType")).toInt());
    op.offset = byteNumber(o.value(key("offset")));
    op.indices = o.value(key("indices")).toString();
    op.instances = o.value(key("instances")).toInt(1);
    for (const QJsonValue &u : o.value(key("uniforms")).toArray())
        op.uniforms.push_back(readUniform(u.toObject()));
    for (const QJsonValue &a : o.value(key("attributes")).toArray())
        op.attributes.push_back(readAttribute(a.toObject()));
    op.stack = readStack(o.value(key("stack")));
    return op;
}

QString whereText(const QJsonValue &where)
{
    const QJsonObject o = where.toObject();
    if (o.isEmpty())
        return {};
    return QStringLiteral("%1:%2: ")
        .arg(o.value(key("file")).toString())
        .arg(o.value(key("line")).toInt());
}

} // namespace

QString callSiteText(const CallStack &stack)
{
    if (stack.empty())
        return {};
    return QStringLiteral("%1:%2").arg(stack.front().file).arg(stack.front().line);
}

const CapturedUniform *CapturedOp::uniform(const QString &name) const
{
    for (const CapturedUniform &u : uniforms)
        if (u.name == name)
            return &u;
    return nullptr;
}

const CapturedAttribute *CapturedOp::attribute(const QString &name) const
{
    for (const CapturedAttribute &a : attributes)
        if (a.name == name)
            return &a;
    return nullptr;
}

const CapturedProgram *PageCapture::program(int id) const
{
    for (const CapturedProgram &p : programs)
        if (p.id == id)
            return &p;
    return nullptr;
}

const CapturedBuffer *PageCapture::buffer(const QString &name) const
{
    const auto it = buffers.find(name);
    return it == buffers.end() ? nullptr : &it->second;
}

std::vector<const CapturedOp *> PageCapture::draws() const
{
    std::vector<const CapturedOp *> out;
    for (const CapturedOp &op : ops)
        if (op.kind == CapturedOp::Kind::Draw)
            out.push_back(&op);
    return out;
}

namespace {

// The page, its frame and the canvas's pixels, checked against its size.
Result<> readCanvas(const QJsonObject &o, PageCapture &c)
{
    c.webgl = o.value(key("webgl")).toInt();
    c.page = o.value(key("page")).toString();
    c.frame = o.value(key("frame")).toInt();
    c.animated = o.value(key("animated")).toBool();
    const QJsonObject canvas = o.value(key("canvas")).toObject();
    c.canvas = QSize(canvas.value(key("width")).toInt(), canvas.value(key("height")).toInt());
    c.pixels = QByteArray::fromBase64(o.value(key("pixels")).toString().toLatin1());
    if (!c.pixels.isEmpty()
        && (c.canvas.width() <= 0 || c.canvas.height() <= 0 || c.canvas.width() > 16384
            || c.canvas.height() > 16384
            || c.pixels.size() != qsizetype(c.canvas.width()) * c.canvas.height() * 4))
        return fail(PageCaptureWords::tr("key \"pixels\": %1 bytes for a canvas of %2x%3")
                        .arg(c.pixels.size())
                        .arg(c.canvas.width())
                        .arg(c.canvas.height()));
    return {};
}

// The frame's clears and draws, within what PhongLab checks.
Result<> readOps(const QJsonObject &o, PageCapture &c)
{
    const QJsonArray ops = o.value(key("draws")).toArray();
    if (ops.size() > kMaxCapturedOps)
        return fail(PageCaptureWords::tr("key \"draws\": %1 clears and draws in one frame, more "
                                         "than PhongLab checks (%2)")
                        .arg(ops.size())
                        .arg(kMaxCapturedOps));
    qint64 vertices = 0;
    for (const QJsonValue &op : ops) {
        c.ops.push_back(readOp(op.toObject()));
        vertices += std::max(0, c.ops.back().count) * qint64(std::max(1, c.ops.back().instances));
    }
    if (vertices > kMaxCapturedVertices)
        return fail(PageCaptureWords::tr("key \"draws\": %1 vertices in one frame, more than "
                                         "PhongLab checks (%2)")
                        .arg(vertices)
                        .arg(kMaxCapturedVertices));
    return {};
}

void readProgramsAndBuffers(const QJsonObject &o, PageCapture &c)
{
    for (const QJsonValue &value : o.value(key("programs")).toArray()) {
        const QJsonObject p = value.toObject();
        c.programs.push_back({p.value(key("id")).toInt(), p.value(key("vertex")).toString(),
                              p.value(key("fragment")).toString(), p.value(key("linked")).toBool(),
                              p.value(key("drawn")).toBool(), p.value(key("log")).toString()});
    }
    const QJsonObject buffers = o.value(key("buffers")).toObject();
    for (auto it = buffers.begin(); it != buffers.end(); ++it) {
        const QJsonObject b = it.value().toObject();
        c.buffers[it.key()] = {QByteArray::fromBase64(b.value(key("bytes")).toString().toLatin1()),
                               readStack(b.value(key("set_at")))};
    }
}

// What the run met besides the drawing: the steps, errors, and the files
// served and refused.
void readRunNotes(const QJsonObject &o, PageCapture &c)
{
    for (const QJsonValue &value : o.value(key("steps")).toArray())
        c.steps.push_back({value.toObject().value(key("step")).toString(),
                           value.toObject().value(key("problem")).toString()});
    c.extraContexts = o.value(key("extra_contexts")).toInt();
    for (const QJsonValue &value : o.value(key("errors")).toArray())
        c.errors.push_back(whereText(value.toObject().value(key("where")))
                           + value.toObject().value(key("message")).toString());
    for (const QJsonValue &value : o.value(key("console_errors")).toArray())
        c.consoleErrors.push_back(value.toString());
    for (const QJsonValue &value : o.value(key("refused")).toArray())
        c.refused.push_back(value.toObject().value(key("kind")).toString() + QLatin1Char(' ')
                            + value.toObject().value(key("url")).toString());
    for (const QJsonValue &value : o.value(key("served")).toArray())
        c.served.push_back(value.toString());
}

} // namespace

Result<PageCapture> readPageCapture(const QByteArray &json)
{
    QJsonParseError error{};
    const QJsonDocument document = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError)
        return fail(PageCaptureWords::tr("not JSON at byte %1: %2")
                        .arg(error.offset)
                        .arg(error.errorString()));
    const QJsonObject o = document.object();
    if (o.value(key("format")).toInt() != 1)
        return fail(PageCaptureWords::tr("not a page capture of format 1 (key \"format\")"));
    PageCapture c;
    if (const Result<> canvas = readCanvas(o, c); !canvas)
        return fail(canvas.error());
    if (const Result<> ops = readOps(o, c); !ops)
        return fail(ops.error());
    readProgramsAndBuffers(o, c);
    readRunNotes(o, c);
    return c;
}

} // namespace phonglab
