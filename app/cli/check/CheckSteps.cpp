#include "CheckSteps.h"

#include "cli/common/StageOptions.h"
#include "core/project/ProjectShader.h"
#include "core/reference/ImageMetrics.h"
#include "mesh/loading/SceneMeshes.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/QtImages.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct CheckStepsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::CheckSteps)
};

ShaderDiagnostic inputError(const QString &file, const QString &message)
{
    ShaderDiagnostic d;
    d.file = file;
    d.message = message;
    return d;
}

QStringList buildWarnings(const std::vector<ShaderDiagnostic> &compilerMessages)
{
    QStringList out;
    for (const ShaderDiagnostic &d : compilerMessages)
        if (!d.isError())
            out << d.format();
    return out;
}

ShaderDiagnostic sceneError(const QString &path, const SceneLoadResult &loaded)
{
    ShaderDiagnostic d = inputError(path, loaded.error);
    d.line = loaded.errorLine;
    d.column = loaded.errorColumn;
    return d;
}

namespace {

// The file that declares uniform `name`: the vertex stage's, else the
// fragment's.
QString declaringFile(const QString &name, const CheckFindings &findings, const StageFiles &files)
{
    const bool inVertex =
        !findings.stages.empty() && uniformDeclarationLine(findings.stages.front().text, name) > 0;
    return inVertex ? files.vertex : files.fragment;
}

// The first stage file that cannot be read, as that file's error (check
// --json's "file"); none where both can.
std::optional<ShaderDiagnostic> unreadableStage(const StageFiles &files)
{
    for (const QString &path : {files.vertex, files.fragment}) {
        if (isShaderLocator(path)) {
            if (const Result<ProjectShader> shader = shaderAtLocator(path); !shader)
                return inputError(path.left(path.lastIndexOf(QLatin1Char('#'))), shader.error());
            continue;
        }
        if (QFile file(path); !file.open(QIODevice::ReadOnly))
            return inputError(
                path, CheckStepsWords::tr("cannot read shader: %1").arg(file.errorString()));
    }
    return std::nullopt;
}

// A program that did not build: its compile errors, or one saying so.
void addCompileErrors(const BuildReport &program, const StageFiles &files, CheckFindings *findings)
{
    for (const ShaderDiagnostic &d : program.diagnostics)
        if (d.isError())
            findings->errors.push_back(d);
    if (findings->errors.empty())
        findings->errors.push_back(
            inputError(files.fragment, CheckStepsWords::tr("the shaders did not compile")));
}

// Nothing PhongLab could not bind may decide the verdict: the student's
// names are PhongLab's gap, never the student's mistake.
void addBindingErrors(const ProgramFindings &found, const StageFiles &files,
                      CheckFindings *findings)
{
    for (const QString &problem : found.problems)
        findings->errors.push_back(inputError(QStringLiteral("--bind"), problem));
    for (const UnboundUniform &unbound : found.unbound)
        findings->errors.push_back(
            inputError(declaringFile(unbound.name, *findings, files), unboundMessage(unbound)));
    for (const QString &conflict : found.conflicts)
        findings->errors.push_back(inputError(QStringLiteral("--bind"), conflict));
}

} // namespace

CheckDrawing drawForCheck(const CheckInput &input, const Scene &scene)
{
    CheckDrawing drawing;
    CheckFindings &findings = drawing.findings;
    const auto fail = [&](const QString &file, const QString &message) {
        findings.errors.push_back(inputError(file, message));
        return std::move(drawing);
    };
    SceneMeshes meshes = loadSceneMeshes(scene);
    if (!meshes.ok())
        return fail(input.scenePath, meshes.error);
    // Builtins too: the reference casts the triangles the GPU draws.
    for (const SceneObject &object : scene.objects)
        drawing.objectMeshes.push_back(meshes.entries.value(meshKey(scene, object)).mesh);

    OffscreenRenderer offscreen;
    if (const Result<> created = offscreen.create(); !created)
        return fail(QString(), created.error());
    Renderer &renderer = offscreen.renderer();
    if (const Result<> set = renderer.setScene(scene, std::move(meshes)); !set)
        return fail(input.scenePath, set.error());
    const StageFiles files =
        chooseStageFiles(scene, input.vertexPath, input.fragmentPath, input.methodChosen);
    if (const std::optional<ShaderDiagnostic> unreadable = unreadableStage(files))
        return fail(unreadable->file, unreadable->message);
    const Result<BuildReport> built = buildStages(renderer, files, &findings.stages);
    if (!built)
        return fail(QString(), built.error());
    const BuildReport &program = *built;
    drawing.compilerMessages = program.diagnostics;
    findings.warnings << buildWarnings(drawing.compilerMessages);
    if (!program.ok) {
        addCompileErrors(program, files, &findings);
        return drawing;
    }
    const ProgramFindings found = findProgramFindings(renderer.program(), scene);
    findings.bindings = found.bindings;
    drawing.lightCapacity = found.lightCapacity;
    findings.notes << found.bindings.notes;
    addBindingErrors(found, files, &findings);
    if (!findings.errors.empty())
        return drawing;
    const Scene &checked = found.checked;
    if (!found.lightsNote.isEmpty()) {
        findings.notes << found.lightsNote;
        renderer.updateSceneParameters(checked);
    }
    drawing.image = offscreen.renderImage(input.size);
    if (drawing.image.isNull())
        return fail(QString(), CheckStepsWords::tr("rendering failed"));
    findings.precision =
        measurePrecision(offscreen, findings.stages, checked, input.size, drawing.image);
    return drawing;
}

Scene sceneForCheck(const Scene &scene, std::optional<int> lightCapacity)
{
    QString unused;
    return sceneForCapacity(scene, lightCapacity, &unused);
}

namespace {

QByteArray stageText(const std::vector<ShaderStageText> &stages, bool vertex)
{
    for (const ShaderStageText &s : stages)
        if (s.vertex == vertex)
            return s.text.toUtf8();
    return {};
}

} // namespace

Verdict checkDrawing(CheckFindings *findings, const QImage &image, const CheckReference &reference,
                     int toleranceSteps, std::optional<PhongEquation> equation,
                     const QString &scenePath)
{
    findings->report = checkRender(toRgbImage(image), reference, toleranceSteps, equation);
    nameWhatTheCodeDoes(findings->report, stageText(findings->stages, true),
                        stageText(findings->stages, false));
    if (!findings->report.comparable()) {
        findings->errors.push_back(inputError(
            scenePath,
            CheckStepsWords::tr("nothing to compare: no surface away from silhouettes in "
                                "this view at %1x%2")
                .arg(image.width())
                .arg(image.height())));
        return Verdict::Error;
    }
    return findings->report.passed() ? Verdict::Pass : Verdict::Fail;
}

// --- the child's answer ----------------------------------------------------

namespace {

QJsonObject diagnosticJson(const ShaderDiagnostic &d)
{
    return {{QStringLiteral("step"), int(d.step)}, {QStringLiteral("error"), d.isError()},
            {QStringLiteral("file"), d.file},      {QStringLiteral("line"), d.line},
            {QStringLiteral("column"), d.column},  {QStringLiteral("message"), d.message}};
}

ShaderDiagnostic diagnosticFromJson(const QJsonObject &o)
{
    ShaderDiagnostic d;
    d.step =
        BuildStep(std::clamp(o.value(QStringLiteral("step")).toInt(), 0, int(BuildStep::Link)));
    d.severity = o.value(QStringLiteral("error")).toBool(true)
        ? ShaderDiagnostic::Severity::Error
        : ShaderDiagnostic::Severity::Warning;
    d.file = o.value(QStringLiteral("file")).toString();
    d.line = o.value(QStringLiteral("line")).toInt();
    d.column = o.value(QStringLiteral("column")).toInt();
    d.message = o.value(QStringLiteral("message")).toString();
    return d;
}

QJsonArray diagnosticsJson(const std::vector<ShaderDiagnostic> &list)
{
    QJsonArray out;
    for (const ShaderDiagnostic &d : list)
        out.append(diagnosticJson(d));
    return out;
}

std::vector<ShaderDiagnostic> diagnosticsFromJson(const QJsonValue &value)
{
    std::vector<ShaderDiagnostic> out;
    for (const QJsonValue &d : value.toArray())
        out.push_back(diagnosticFromJson(d.toObject()));
    return out;
}

} // namespace

QJsonObject drawingJson(const CheckDrawing &drawing)
{
    const CheckFindings &o = drawing.findings;
    QJsonArray stages;
    for (const ShaderStageText &s : o.stages)
        stages.append(QJsonObject{{QStringLiteral("path"), s.path},
                                  {QStringLiteral("text"), s.text},
                                  {QStringLiteral("vertex"), s.vertex}});
    // Only what the verdict and its report read: the bound and the
    // explicitly unbound variables (the type decides nothing after binding).
    QJsonArray variables;
    for (const VariableBinding &b : o.bindings.variables)
        if (b.meaning || b.isExplicit)
            variables.append(
                QJsonObject{{QStringLiteral("name"), b.variable.name},
                            {QStringLiteral("meaning"),
                             b.meaning ? QJsonValue(bindingMeaningKey(*b.meaning)) : QJsonValue()},
                            {QStringLiteral("explicit"), b.isExplicit}});
    return {{QStringLiteral("errors"), diagnosticsJson(o.errors)},
            {QStringLiteral("compiler"), diagnosticsJson(drawing.compilerMessages)},
            {QStringLiteral("stages"), stages},
            {QStringLiteral("variables"), variables},
            {QStringLiteral("notes"), QJsonArray::fromStringList(o.notes)},
            {QStringLiteral("precision"), precisionJson(o.precision)},
            {QStringLiteral("light_capacity"),
             drawing.lightCapacity ? QJsonValue(*drawing.lightCapacity) : QJsonValue()}};
}

CheckDrawing drawingFromJson(const QJsonObject &json)
{
    CheckDrawing drawing;
    CheckFindings &o = drawing.findings;
    o.errors = diagnosticsFromJson(json.value(QStringLiteral("errors")));
    drawing.compilerMessages = diagnosticsFromJson(json.value(QStringLiteral("compiler")));
    o.warnings << buildWarnings(drawing.compilerMessages);
    for (const QJsonValue &v : json.value(QStringLiteral("stages")).toArray()) {
        const QJsonObject s = v.toObject();
        o.stages.push_back({s.value(QStringLiteral("path")).toString(),
                            s.value(QStringLiteral("text")).toString(),
                            s.value(QStringLiteral("vertex")).toBool()});
    }
    for (const QJsonValue &v : json.value(QStringLiteral("variables")).toArray()) {
        const QJsonObject b = v.toObject();
        VariableBinding binding;
        binding.variable.name = b.value(QStringLiteral("name")).toString();
        binding.meaning = bindingMeaningFromKey(b.value(QStringLiteral("meaning")).toString());
        binding.isExplicit = b.value(QStringLiteral("explicit")).toBool();
        o.bindings.variables.push_back(binding);
    }
    for (const QJsonValue &v : json.value(QStringLiteral("notes")).toArray())
        o.notes << v.toString();
    o.precision = precisionFromJson(json.value(QStringLiteral("precision")).toObject());
    if (const QJsonValue c = json.value(QStringLiteral("light_capacity")); c.isDouble())
        drawing.lightCapacity = c.toInt();
    return drawing;
}

} // namespace phonglab::cli
