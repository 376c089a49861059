#include "ProgramFindings.h"

#include "core/check/BindingConflicts.h"
#include "core/program/CoursePrelude.h"
#include "core/reference/ImageMetrics.h"
#include "render/gl/QtImages.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ProgramFindingsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ProgramFindings)
};

namespace {

bool allZero(const UniformSnapshot &snapshot, const VariableBinding &b)
{
    for (const UniformValue &v : snapshot.values) {
        const QString name = QString::fromUtf8(v.name);
        if (name != b.variable.name && !name.startsWith(b.variable.name + QLatin1Char('[')))
            continue;
        for (int i = 0; i < v.components; ++i) {
            const bool zero = v.kind == UniformValue::Kind::Float ? v.floats[i] == 0.0f
                : v.kind == UniformValue::Kind::Int               ? v.ints[i] == 0
                                                                  : v.uints[i] == 0u;
            if (!zero)
                return false;
        }
    }
    return true;
}

bool sceneGivesValue(const Scene &scene, const QString &name)
{
    for (const auto &[key, values] : scene.uniforms)
        if (key == name || key.startsWith(name + QLatin1Char('[')))
            return true;
    return false;
}

// PhongLab's own name for each meaning: a binding under it says nothing new.
QString ownName(BindingMeaning meaning)
{
    switch (meaning) {
    case BindingMeaning::Model: return QStringLiteral("modelMatrix");
    case BindingMeaning::View: return QStringLiteral("viewMatrix");
    case BindingMeaning::Projection: return QStringLiteral("projectionMatrix");
    case BindingMeaning::ModelView: return QStringLiteral("modelViewMatrix");
    case BindingMeaning::NormalMatrix: return QStringLiteral("normalMatrix");
    case BindingMeaning::LightPosition: return QStringLiteral("lightPosition");
    case BindingMeaning::LightCount: return QStringLiteral("lightCount");
    case BindingMeaning::LightDiffuse: return QStringLiteral("Id");
    case BindingMeaning::LightSpecular: return QStringLiteral("Is");
    case BindingMeaning::Ambient: return QStringLiteral("Ia");
    default: return bindingMeaningKey(meaning);
    }
}

} // namespace

std::vector<UnboundUniform> unboundUniforms(ShaderProgram &program, const Scene &scene)
{
    std::vector<UnboundUniform> out;
    const UniformSnapshot snapshot = program.snapshot();
    for (const VariableBinding *b : program.bindings().unboundUniforms()) {
        if (b->isExplicit || b->variable.type == GlslType::Other
            || sceneGivesValue(scene, b->variable.name) || !allZero(snapshot, *b))
            continue;
        out.push_back({b->variable.name, b->variable.type, likelyMeaning(b->variable)});
    }
    return out;
}

int uniformDeclarationLine(const QString &text, const QString &name)
{
    const QRegularExpression declared(
        QStringLiteral(R"(\buniform\b[^;]*\b%1\b)").arg(QRegularExpression::escape(name)));
    const QRegularExpressionMatch m = declared.match(text);
    if (!m.hasMatch())
        return 0;
    return int(QStringView(text).left(m.capturedEnd()).count(QLatin1Char('\n'))) + 1;
}

QString unboundSentence(const UnboundUniform &unbound)
{
    return ProgramFindingsWords::tr("uniform %1 (%2) is bound to nothing, so the shader reads zero")
        .arg(unbound.name, glslTypeSpelling(unbound.type));
}

ProgramFindings findProgramFindings(ShaderProgram &program, const Scene &scene)
{
    ProgramFindings found;
    found.bindings = program.bindings();
    found.lightCapacity = found.bindings.lightCapacity();
    found.problems = found.bindings.problems;
    found.unbound = unboundUniforms(program, scene);
    found.conflicts = bindingConflicts(found.bindings, scene);
    found.checked = sceneForCapacity(scene, found.lightCapacity, &found.lightsNote);
    return found;
}

QString bindingsText(const ProgramBindings &bindings)
{
    QStringList parts;
    bool worthSaying = false;
    for (const VariableBinding &b : bindings.variables) {
        if (b.meaning)
            worthSaying = worthSaying || b.isExplicit || b.variable.name != ownName(*b.meaning);
        else if (b.isExplicit)
            worthSaying = true;
        else
            continue; // the user's own uniforms: the Uniforms dock's, not a binding
        parts << QStringLiteral("%1=%2").arg(
            b.variable.name, b.meaning ? bindingMeaningKey(*b.meaning) : kUnboundWord);
    }
    return worthSaying ? parts.join(QStringLiteral(", ")) : QString();
}

QStringList bindingsByUseText(const ProgramBindings &bindings)
{
    QStringList out;
    for (const VariableBinding &b : bindings.variables)
        if (b.meaning && b.byUse)
            out << ProgramFindingsWords::tr("%1=%2: %3 (%4 shader, line %5)")
                       .arg(b.variable.name, bindingMeaningKey(*b.meaning), b.byUse->reason,
                            stageName(b.byUse->stage))
                       .arg(b.byUse->line);
    return out;
}

Scene sceneForCapacity(const Scene &scene, std::optional<int> capacity, QString *note)
{
    const int enabled = scene.enabledLightCount();
    if (!capacity || enabled <= *capacity)
        return scene;
    Scene out = scene;
    int kept = 0;
    for (PointLight &l : out.lights)
        if (l.enabled && kept++ >= *capacity)
            l.enabled = false;
    *note = ProgramFindingsWords::tr(
                "the shader takes %1 %2 (its light uniforms have room for no "
                "more) and the scene has %3 enabled: checked with the first %1 alone")
                .arg(*capacity)
                .arg(*capacity == 1 ? ProgramFindingsWords::tr("light")
                                    : ProgramFindingsWords::tr("lights"))
                .arg(enabled);
    return out;
}

PrecisionFinding declaredPrecision(const std::vector<ShaderStageText> &stages, const Scene &checked)
{
    PrecisionFinding finding;
    finding.checkedAt = checked.course.precision;
    for (const ShaderStageText &s : stages) {
        const ShaderStage stage = s.vertex ? ShaderStage::Vertex : ShaderStage::Fragment;
        for (const QString &lower :
             coursePreludeFor(s.text.toUtf8(), stage, checked.course).lowerPrecisions)
            if (!finding.declared.contains(lower))
                finding.declared << lower;
    }
    return finding;
}

PrecisionFinding measurePrecision(OffscreenRenderer &offscreen,
                                  const std::vector<ShaderStageText> &stages, const Scene &checked,
                                  QSize size, const QImage &checkedImage,
                                  const UniformSnapshot *values)
{
    PrecisionFinding finding = declaredPrecision(stages, checked);
    if (finding.declared.isEmpty() || finding.checkedAt != PrecisionRule::Highp)
        return finding;
    StageSources sources;
    for (const ShaderStageText &s : stages)
        (s.vertex ? sources.vertex : sources.fragment) = ShaderSource{s.path, s.text.toUtf8()};
    Scene asWritten = checked;
    asWritten.course.precision = PrecisionRule::AsWritten;
    Renderer &renderer = offscreen.renderer();
    renderer.updateSceneParameters(asWritten);
    const BuildReport built = renderer.setProgramSources(sources.vertex, sources.fragment);
    if (!built.ok) {
        for (const ShaderDiagnostic &d : built.diagnostics)
            if (d.isError()) {
                finding.asWrittenError = d.format();
                break;
            }
        return finding;
    }
    if (values)
        renderer.restoreUniforms(*values);
    const QImage image = offscreen.renderImage(size);
    if (image.isNull())
        return finding;
    const ImageComparison c = compareImages(toRgbImage(image), toRgbImage(checkedImage));
    finding.asWrittenMaxError = c.maxError;
    finding.asWrittenPsnr = c.psnr;
    return finding;
}

} // namespace phonglab
