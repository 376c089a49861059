#pragma once
// What each fuzz target does with one input, shared by the libFuzzer targets
// (tests/fuzz/fuzz_<name>.cpp) and the context-free regression test
// (tests/unit/tst_fuzzregressions.cpp), so a file under tests/data/fuzz/
// goes through exactly the code path the fuzzer found it on.
//
// Every target also checks the promises its entry point makes about what
// it returns (a loaded mesh is valid, a parsed scene writes back to the
// same scene, ...); a broken promise aborts, which the fuzzer reports as a
// crash like any other.
//
// Header-only on purpose: the fuzz build links it with libFuzzer, the unit
// test with QtTest, and neither needs a library of its own.

#include "core/program/BindingsByUse.h"
#include "core/program/BrowserRules.h"
#include "core/program/CoursePrelude.h"
#include "core/program/ShaderLint.h"
#include "core/program/UniformAnnotations.h"
#include "core/project/HtmlShaders.h"
#include "core/project/ProjectSave.h"
#include "core/project/ProjectShader.h"
#include "core/scene/SceneJson.h"
#include "core/session/RecoveryJournal.h"
#include "core/view/CameraPath.h"
#include "mesh/loading/MeshCache.h"
#include "mesh/loading/MeshLoader.h"
#include "render/program/ShaderDiagnostic.h"

#include <QBuffer>
#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>
#include <QStringList>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <unistd.h>

namespace phonglab::fuzz {

// What an entry point made of one input: loaded/parsed (ok) or the error it
// gave. Parsers that only return a list (shader logs, uniforms) are always ok.
struct Outcome {
    bool ok = false;
    QString error;
};

// Every target, by the name used in fuzz_<name>, tests/fuzz/corpus/<name>
// and tests/data/fuzz/<name>.
inline const QStringList &targetNames()
{
    static const QStringList names{"obj",        "ply",        "off",         "stl",      "om",
                                   "meshcache",  "scene",      "shaderlog",   "uniforms", "journal",
                                   "camerapath", "coursecode", "htmlshaders", "jsshaders"};
    return names;
}

[[noreturn]] inline void brokenPromise(const char *target, const char *what)
{
    std::fprintf(stderr, "fuzz_%s: broken promise: %s\n", target, what);
    std::abort();
}

// One scratch file per process and file name: the entry points that read
// files get the input under the name (and suffix) they dispatch on.
inline QString scratchPath(const QString &fileName)
{
    // Made on first use, removed at a normal exit (a crash leaves it for
    // the post-mortem).
    static const struct ScratchDir {
        QString path;
        ScratchDir()
        {
            QString base = qEnvironmentVariable("TMPDIR");
            if (base.isEmpty())
                base = QStringLiteral("/tmp");
            path = QStringLiteral("%1/phonglab-fuzz-%2").arg(base).arg(::getpid());
            QDir().mkpath(path);
        }
        ~ScratchDir() { QDir(path).removeRecursively(); }
    } dir;
    return dir.path + QLatin1Char('/') + fileName;
}

inline bool writeScratch(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate)
        && file.write(bytes) == bytes.size();
}

inline void checkMesh(const char *target, const MeshLoadResult &result)
{
    if (!result.ok()) {
        if (result.error.isEmpty())
            brokenPromise(target, "a failed load without an error message");
        return;
    }
    const MeshData &mesh = *result.mesh;
    if (!mesh.isValid())
        brokenPromise(
            target,
            "a loaded mesh that is not valid (empty, normals do not match, index out of range)");
    if (mesh.indices.empty())
        brokenPromise(target, "a loaded mesh without triangles");
    for (const glm::vec3 &p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            brokenPromise(target, "a loaded mesh with a NaN or infinite position");
    for (const glm::vec3 &n : mesh.normals)
        if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z))
            brokenPromise(target, "a loaded mesh with a NaN or infinite normal");
    if (result.stats.triangles != qint64(mesh.triangleCount())
        || result.stats.vertices != qint64(mesh.positions.size()))
        brokenPromise(target, "stats that do not describe the loaded mesh");
}

// OBJ, PLY, OFF, STL, OM: the input as a file with the format's suffix,
// through importMeshFile, what the app's import child runs.
inline Outcome runMesh(const std::string &suffix, const QByteArray &bytes)
{
    const QString path = scratchPath(QStringLiteral("input.") + QString::fromStdString(suffix));
    if (!writeScratch(path, bytes))
        brokenPromise(suffix.c_str(), "cannot write the scratch file");
    const MeshLoadResult result = importMeshFile(path, NormalOptions{}, LoadProgress{});
    checkMesh(suffix.c_str(), result);
    return {result.ok(), result.error};
}

// A mesh cache entry (the import child's answer, the cache file): any key.
inline Outcome runMeshCache(const QByteArray &bytes)
{
    QByteArray copy = bytes;
    QBuffer buffer(&copy);
    buffer.open(QIODevice::ReadOnly);
    const std::optional<MeshLoadResult> result = MeshCache::decode(buffer, std::nullopt);
    if (!result)
        return {false, QStringLiteral("refused")};
    if (!result->mesh || !result->mesh->isValid())
        brokenPromise("meshcache", "an accepted entry with an invalid mesh");
    return {true, {}};
}

// A scene file's text. What parses must write back to the same scene.
inline Outcome runScene(const QByteArray &bytes)
{
    const SceneLoadResult result = parseScene(bytes, QStringLiteral("/phonglab-fuzz-base"));
    if (!result.ok()) {
        if (result.error.isEmpty())
            brokenPromise("scene", "a refused scene without an error message");
        return {false, result.error};
    }
    const SceneLoadResult again =
        parseScene(sceneToJson(*result.scene), QStringLiteral("/phonglab-fuzz-base"));
    if (!again.ok()) {
        std::fprintf(stderr, "fuzz_scene: the written scene does not parse: %s\n",
                     qPrintable(again.error));
        brokenPromise("scene", "sceneToJson wrote a scene that parseScene refuses");
    }
    if (!(*again.scene == *result.scene))
        brokenPromise("scene", "sceneToJson + parseScene changed the scene");
    return {true, {}};
}

// A driver info log. Byte 0 picks the stage and how many prologue lines the
// driver saw; the rest is the log, then (after the first NUL byte, if any)
// the source text its columns are mapped onto.
inline Outcome runShaderLog(const QByteArray &bytes)
{
    const unsigned char head = bytes.isEmpty() ? 0 : static_cast<unsigned char>(bytes[0]);
    const BuildStep step = BuildStep(head % 3);
    const int prologueLines = (head / 3) % 16;
    const QByteArray rest = bytes.mid(1);
    const qsizetype nul = rest.indexOf('\0');
    const QByteArray log = nul < 0 ? rest : rest.left(nul);
    const QByteArray code = nul < 0 ? QByteArray() : rest.mid(nul + 1);
    std::vector<ShaderDiagnostic> diagnostics =
        parseShaderLog(QString::fromUtf8(log), step, QStringLiteral("shader.frag"), prologueLines);
    mapColumnsToSource(diagnostics, code);
    const std::vector<ShaderDiagnostic> compilers = diagnostics;
    pointAtMissingSemicolons(diagnostics, code);
    for (std::size_t i = 0; i < diagnostics.size(); ++i) {
        const ShaderDiagnostic &d = diagnostics[i];
        if (d.line < 0 || d.column < 0)
            brokenPromise("shaderlog", "a negative line or column");
        if (d.line > compilers[i].line)
            brokenPromise("shaderlog", "a missing ';' moved to a later line");
        (void)d.format();
    }
    return {true, {}};
}

// A student's shader text as the course's page hands it over: the lint of
// what the image cannot show, the page's prelude (precision, three.js,
// defines) and the words on an undefined token. The first byte picks the
// stage and the precision rule; the rest is the text.
inline Outcome runCourseCode(const QByteArray &bytes)
{
    const unsigned char head = bytes.isEmpty() ? 0 : static_cast<unsigned char>(bytes[0]);
    const QByteArray code = bytes.mid(1);
    for (const LintFinding &f : lintShader(code)) {
        if (f.line < 1 || f.column < 1 || f.variable.isEmpty() || f.message.isEmpty())
            brokenPromise("coursecode", "a finding without a place, a name or a message");
        if (f.line > code.count('\n') + 1)
            brokenPromise("coursecode", "a finding past the last line");
    }
    CourseOptions options;
    options.precision = head & 1 ? PrecisionRule::AsWritten : PrecisionRule::Highp;
    options.defines[QStringLiteral("NUM_LIGHTS")] = QStringLiteral("2");
    const CoursePrelude prelude =
        coursePreludeFor(code, head & 2 ? ShaderStage::Fragment : ShaderStage::Vertex, options);
    // The prelude goes before #line: a line of its own may not break one.
    if (!prelude.text.isEmpty() && !prelude.text.endsWith('\n'))
        brokenPromise("coursecode", "a prelude that does not end its last line");
    const QString message = QString::fromUtf8(code.left(200));
    if (!explainUndefinedToken(message, options.defines).startsWith(message))
        brokenPromise("coursecode", "an explanation that changed the compiler's words");
    // The browser's rules insert, never remove, and keep every line.
    const BrowserRewrite browser =
        applyBrowserRules(code, head & 2 ? ShaderStage::Fragment : ShaderStage::Vertex);
    qsizetype inserted = 0;
    for (const SourceInsertion &at : browser.insertions) {
        inserted += at.text.size();
        if (at.offset < 0 || at.offset > code.size() || at.text.contains('\n'))
            brokenPromise("coursecode", "an insertion outside the text or across a line");
    }
    if (browser.code.size() != code.size() + inserted
        || browser.code.count('\n') != code.count('\n'))
        brokenPromise("coursecode", "a rewrite that lost text or moved a line");
    // Binding by use binds only what nothing bound, and says where.
    std::vector<ShaderVariable> variables;
    for (const UniformDeclaration &d : parseUniformDeclarations(QString::fromUtf8(code)))
        variables.push_back({d.name,
                             d.type == QLatin1String("mat4")        ? GlslType::Mat4
                                 : d.type == QLatin1String("float") ? GlslType::Float
                                                                    : GlslType::Vec3,
                             std::max(1, d.arraySize), d.isArray, false});
    ProgramBindings bindings = bindVariables(variables, {});
    bindByUse(bindings, code, code);
    for (const VariableBinding &b : bindings.variables) {
        if (b.byUse && (b.byUse->line < 1 || b.byUse->line > code.count('\n') + 1))
            brokenPromise("coursecode", "a binding by use on no line of the text");
        if (b.byUse && !b.meaning)
            brokenPromise("coursecode", "a reason for no meaning");
    }
    return {true, {}};
}

// What every text found in a page or a script promises: one file offset
// per byte, each inside the file.
inline void checkFoundTexts(const char *target, const QByteArray &file,
                            const std::vector<FoundText> &texts)
{
    for (const FoundText &t : texts) {
        if (t.from.size() != std::size_t(t.value.size()))
            brokenPromise(target, "a text without one offset per byte");
        for (const qsizetype at : t.from)
            if (at < 0 || at >= file.size())
                brokenPromise(target, "an offset outside the file");
        if (t.begin < 0 || t.end < t.begin || t.end > file.size())
            brokenPromise(target, "a range outside the file");
    }
}

// The shaders read from those bytes as a file named `path`: named, on a line of the file,
// laid out from that line, and a writable one saved back unchanged leaves
// the file as it was.
inline void checkShadersOf(const char *target, const QString &path, const QByteArray &bytes);

// The shaders of an HTML page (gumbo, then each inline script's JavaScript).
inline Outcome runHtmlShaders(const QByteArray &bytes)
{
    checkFoundTexts("htmlshaders", bytes, shaderTextsInHtml(bytes));
    checkShadersOf("htmlshaders", QStringLiteral("page.html"), bytes);
    return {true, {}};
}

inline void checkShadersOf(const char *target, const QString &path, const QByteArray &bytes)
{
    for (const ProjectShader &s : shadersInText(path, bytes)) {
        // Saved back unchanged, a writable shader leaves the file as it was.
        if (s.writable) {
            const Result<QByteArray> saved = withShaderText(bytes, s, s.text);
            if (!saved || *saved != bytes)
                brokenPromise(target, "a writable shader saved back unchanged changed the file");
        }
        if (s.key.isEmpty() || s.line < 1 || s.line > bytes.count('\n') + 1)
            brokenPromise(target, "a shader without a name or a line in the file");
        // Laid out as in the file: its text starts on its line, not before.
        qsizetype first = 0;
        while (first < s.code.size() && (s.code[first] == '\n' || s.code[first] == ' '))
            ++first;
        if (first < s.code.size() && s.code.left(first).count('\n') + 1 < s.line)
            brokenPromise(target, "a text that starts before its line");
    }
}

// JavaScript: the shader strings and the program calls.
inline Outcome runJsShaders(const QByteArray &bytes)
{
    checkFoundTexts("jsshaders", bytes, foundInJs(bytes, 0));
    checkShadersOf("jsshaders", QStringLiteral("script.js"), bytes);
    const std::string_view js(bytes.constData(), std::size_t(bytes.size()));
    qsizetype last = 0;
    for (const JsToken &t : scanJs(js)) {
        if (t.begin < last || t.end <= t.begin || t.end > bytes.size())
            brokenPromise("jsshaders", "tokens out of order or outside the text");
        last = t.end;
    }
    for (const JsProgramCall &call : programCallsInJs(js))
        for (const JsShaderRef *ref : {&call.vertex, &call.fragment})
            if (ref->literalAt && (*ref->literalAt < 0 || *ref->literalAt >= bytes.size()))
                brokenPromise("jsshaders", "a literal outside the text");
    return {true, {}};
}

// Shader text with uniform declarations and their // @range ... comments.
inline Outcome runUniforms(const QByteArray &bytes)
{
    const std::vector<UniformDeclaration> uniforms =
        parseUniformDeclarations(QString::fromUtf8(bytes));
    for (const UniformDeclaration &u : uniforms) {
        if (u.name.isEmpty())
            brokenPromise("uniforms", "a uniform without a name");
        if (u.arraySize < 0)
            brokenPromise("uniforms", "a negative array size");
    }
    return {true, {}};
}

// A shader recovery journal file.
inline Outcome runJournal(const QByteArray &bytes)
{
    const QString path = scratchPath(QStringLiteral("session.journal"));
    if (!writeScratch(path, bytes))
        brokenPromise("journal", "cannot write the scratch file");
    const Result<RecoveryRecord> record = RecoveryJournal::readFile(path);
    if (!record && record.error().isEmpty())
        brokenPromise("journal", "a refused journal without an error message");
    return {record.ok(), record.error()};
}

// A keyframe file of `phonglab bench --path`. What parses has at least two
// cameras, every one finite.
inline Outcome runCameraPath(const QByteArray &bytes)
{
    const Result<CameraPath> path = parseCameraPath(bytes, Camera(), QStringLiteral("fuzz"));
    if (!path) {
        if (path.error().isEmpty())
            brokenPromise("camerapath", "a refused path without an error message");
        return {false, path.error()};
    }
    if (path->cameras.size() < 2)
        brokenPromise("camerapath", "a path of fewer than two frames");
    for (const Camera &c : path->cameras)
        if (!std::isfinite(c.eye.x + c.eye.y + c.eye.z + c.target.x + c.target.y + c.target.z
                           + c.fovDeg))
            brokenPromise("camerapath", "a camera that is not finite");
    return {true, {}};
}

// Dispatch by target name (see targetNames()).
inline Outcome run(std::string_view target, const QByteArray &bytes)
{
    if (target == "obj" || target == "ply" || target == "off" || target == "stl" || target == "om")
        return runMesh(std::string(target), bytes);
    if (target == "meshcache")
        return runMeshCache(bytes);
    if (target == "scene")
        return runScene(bytes);
    if (target == "shaderlog")
        return runShaderLog(bytes);
    if (target == "uniforms")
        return runUniforms(bytes);
    if (target == "journal")
        return runJournal(bytes);
    if (target == "camerapath")
        return runCameraPath(bytes);
    if (target == "coursecode")
        return runCourseCode(bytes);
    if (target == "htmlshaders")
        return runHtmlShaders(bytes);
    if (target == "jsshaders")
        return runJsShaders(bytes);
    std::fprintf(stderr, "phonglab fuzz: unknown target %.*s\n", int(target.size()), target.data());
    std::abort();
}

} // namespace phonglab::fuzz

// Defines the libFuzzer entry point of one target (in fuzz_<name>.cpp).
// PHONGLAB_FUZZ_VERBOSE=1 prints what became of each input (ok or the
// error), e.g. to see what the seeds exercise: fuzz_ply -runs=0 corpus/ply.
#define PHONGLAB_FUZZ_TARGET(name)                                                                 \
    extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)              \
    {                                                                                              \
        static const bool verbose = qEnvironmentVariableIntValue("PHONGLAB_FUZZ_VERBOSE") != 0;    \
        const phonglab::fuzz::Outcome outcome = phonglab::fuzz::run(                               \
            name, QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size))); \
        if (verbose)                                                                               \
            std::fprintf(stderr, "fuzz_%s: %zu bytes: %s\n", name, size,                           \
                         outcome.ok ? "ok" : qPrintable(outcome.error));                           \
        return 0;                                                                                  \
    }
