#pragma once
#include "core/support/Result.h"

#include <QByteArray>
#include <QSize>
#include <QString>
#include <QStringList>

#include <array>
#include <map>
#include <vector>

namespace phonglab {

// What a student's page handed to WebGL in the frame PhongLab captured
// (core/page/capture.js records it in the browser; this reads its JSON,
// the file `capture.json`). Everything a draw depends on is here, so that
// the frame can be drawn again and checked without the browser. GL enums
// are WebGL's numbers (the same as OpenGL's).

// One frame of the JavaScript stack of a call, in the page's own files
// (relative to the project).
struct CallSite {
    QString file;
    int line = 0;
    int column = 0;
    QString function;
};
using CallStack = std::vector<CallSite>;
// "js/main.js:42", the first frame; empty when the stack is.
QString callSiteText(const CallStack &stack);

struct CapturedUniform {
    QString name; // an array without "[0]"
    unsigned glType = 0;
    int size = 1;
    bool isArray = false;
    std::vector<std::vector<double>> values; // per element, as getUniform read it back
    CallStack setAt;                         // the last uniform*() call that set it
};

struct CapturedAttribute {
    QString name;
    unsigned glType = 0; // the shader's type (FLOAT_VEC3, ...)
    int location = -1;
    bool enabled = false;
    // An enabled array: its buffer ("id:version" in PageCapture::buffers) and layout.
    QString buffer;
    int size = 4;           // components
    unsigned component = 0; // FLOAT, UNSIGNED_BYTE, ...
    bool normalized = false;
    int stride = 0; // 0: tightly packed
    qint64 offset = 0;
    bool integer = false;
    int divisor = 0;
    // A disabled one: the constant value every vertex gets.
    std::array<double, 4> value{0, 0, 0, 1};
};

struct CapturedState {
    std::array<int, 4> viewport{0, 0, 0, 0};
    bool depthTest = false;
    unsigned depthFunc = 0x0201; // LESS
    bool depthMask = true;
    bool cullFace = false;
    unsigned cullMode = 0x0405;  // BACK
    unsigned frontFace = 0x0901; // CCW
    bool blend = false;
    std::array<unsigned, 4> blendFunc{1, 0, 1, 0}; // src rgb, dst rgb, src alpha, dst alpha
    std::array<bool, 4> colorMask{true, true, true, true};
    bool scissorTest = false;
    std::array<int, 4> scissor{0, 0, 0, 0};
};

// A clear or a draw to the canvas, in the page's order.
struct CapturedOp {
    enum class Kind {
        Clear,
        Draw
    };
    Kind kind = Kind::Draw;
    CapturedState state;
    // Clear:
    unsigned clearMask = 0;
    std::array<double, 4> clearColor{0, 0, 0, 0};
    double clearDepth = 1;
    // Draw:
    QString drawKind; // "arrays", "elements", "arrays-instanced", ...
    int program = 0;
    unsigned mode = 4; // TRIANGLES
    int first = 0;
    int count = 0;
    unsigned indexType = 0; // elements only
    qint64 offset = 0;      // into the index buffer, in bytes
    QString indices;        // the index buffer ("id:version")
    int instances = 1;
    std::vector<CapturedUniform> uniforms;
    std::vector<CapturedAttribute> attributes;
    CallStack stack;

    bool indexed() const { return !indices.isEmpty() || indexType != 0; }
    const CapturedUniform *uniform(const QString &name) const;
    const CapturedAttribute *attribute(const QString &name) const;
};

// A program as the browser compiled it: the page's replacements, preludes
// and concatenations already done.
struct CapturedProgram {
    int id = 0;
    QString vertex;
    QString fragment;
    bool linked = false;
    bool drawn = false; // in the captured frame
    QString log;
};

struct CapturedBuffer {
    QByteArray bytes;
    CallStack setAt; // the bufferData() call that filled it
};

struct PageStep {
    QString step;
    QString problem; // empty when it was done
};

struct PageCapture {
    int webgl = 0; // 1 or 2; 0: the page made no WebGL context
    QString page;  // the page run, relative to the project
    int frame = 0; // the frame captured (0: the drawing done while loading)
    bool animated = false;
    QSize canvas;
    QByteArray pixels; // RGBA, bottom row first (as readPixels); empty when nothing was drawn
    std::vector<CapturedOp> ops;
    std::vector<CapturedProgram> programs;
    std::map<QString, CapturedBuffer> buffers;
    std::vector<PageStep> steps;
    int extraContexts = 0;
    QStringList errors;        // uncaught exceptions, "file:line: message"
    QStringList consoleErrors; // console.error
    // Network attempts refused, "KIND URL": HTTP ones (refused by PageRun)
    // and others (WebSocket, ...: refused in the page).
    QStringList refused;
    QStringList served; // the files the page was given, relative

    const CapturedProgram *program(int id) const;
    const CapturedBuffer *buffer(const QString &key) const;
    std::vector<const CapturedOp *> draws() const;
};

// What one captured frame may hold for PhongLab to check it (a course's
// page draws a few objects; a hostile capture must not cost hours).
inline constexpr qsizetype kMaxCapturedOps = 4096;
inline constexpr qint64 kMaxCapturedVertices = 32 * 1024 * 1024;

// The capture, or why the JSON is not one (every error located).
Result<PageCapture> readPageCapture(const QByteArray &json);

} // namespace phonglab
