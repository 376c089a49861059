#include "SceneStages.h"

#include "CliCommon.h"
#include "core/scene/ResourcePaths.h"
#include "render/ShaderSource.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QImageWriter>
#include <QSaveFile>

#include <algorithm>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct SceneStagesWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::SceneStages)
};

namespace {

QString stagePath(const QString &fromArgs, const QString &fromScene, const Scene &scene,
                  bool methodChosen, const QString &shipped)
{
    if (!fromArgs.isEmpty())
        return fromArgs;
    if (!fromScene.isEmpty() && !methodChosen)
        return scene.resolveShaderPath(fromScene);
    return shipped;
}

} // namespace

StageFiles chooseStageFiles(const Scene &scene, const QString &vertexArg,
                            const QString &fragmentArg, bool methodChosen)
{
    return {stagePath(vertexArg, scene.vertexShader, scene, methodChosen,
                      shippedShaderPath(scene.shading, ShaderStage::Vertex)),
            stagePath(fragmentArg, scene.fragmentShader, scene, methodChosen,
                      shippedShaderPath(scene.shading, ShaderStage::Fragment))};
}

StageOptions::StageOptions()
    : size(QStringLiteral("size"), SceneStagesWords::tr("image size in pixels, default 800x600"),
           QStringLiteral("WxH"))
    , vertex(QStringLiteral("vertex"),
             SceneStagesWords::tr("vertex shader instead of the scene's or the shading method's"),
             QStringLiteral("FILE"))
    , fragment(QStringLiteral("fragment"),
               SceneStagesWords::tr("fragment shader instead of the scene's or the shading "
                                    "method's"),
               QStringLiteral("FILE"))
    , shading(QStringLiteral("shading"),
              SceneStagesWords::tr("shading method instead of the scene's \"shading\"; one of\n%1")
                  .arg(shadingNames().join(QStringLiteral(", "))),
              QStringLiteral("NAME"))
{
}

QString readSizeOption(const QCommandLineParser &parser, const QCommandLineOption &option,
                       int maxSide, QSize *size)
{
    if (!parser.isSet(option))
        return {};
    const auto parsed = parseSizeArgument(parser.value(option), 1, maxSide);
    if (!parsed)
        return SceneStagesWords::tr("--size: expected WxH with 1..%1 pixels per side, got '%2'")
            .arg(maxSide)
            .arg(parser.value(option));
    *size = *parsed;
    return {};
}

QString readShadingOption(const QCommandLineParser &parser, const QCommandLineOption &option,
                          std::optional<ShadingMethod> *shading)
{
    if (!parser.isSet(option))
        return {};
    *shading = shadingFromName(parser.value(option));
    if (!*shading)
        return SceneStagesWords::tr("--shading: unknown method '%1' (known: %2)")
            .arg(parser.value(option), shadingNames().join(QStringLiteral(", ")));
    return {};
}

Result<BuildReport> buildStages(Renderer &renderer, const StageFiles &files,
                                std::vector<ShaderStageText> *texts)
{
    const Result<StageSources> read = readStageFiles(files.vertex, files.fragment);
    if (!read)
        return fail(read.error());
    const StageSources &stages = *read;
    if (texts) {
        texts->push_back({stages.vertex.name, QString::fromUtf8(stages.vertex.code), true});
        texts->push_back({stages.fragment.name, QString::fromUtf8(stages.fragment.code), false});
    }
    return renderer.setProgramSources(stages.vertex, stages.fragment);
}

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
        QString message = SceneStagesWords::tr("uniform %1 (%2) is bound to nothing, so the shader "
                                               "reads zero")
                              .arg(b->variable.name, glslTypeSpelling(b->variable.type));
        if (const auto likely = likelyMeaning(b->variable))
            message +=
                SceneStagesWords::tr("; if it is %1, add --bind %2=%3 (or \"bindings\" in the "
                                     "scene)")
                    .arg(bindingMeaningDescription(*likely), b->variable.name,
                         bindingMeaningKey(*likely));
        else
            message +=
                SceneStagesWords::tr("; bind it with --bind %1=MEANING (meanings: %2), or give "
                                     "it a value in the scene's \"uniforms\"")
                    .arg(b->variable.name, bindingMeaningKeys().join(QStringLiteral(", ")));
        out.push_back({b->variable.name, message});
    }
    return out;
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
            out << SceneStagesWords::tr("%1=%2: %3 (%4 shader, line %5)")
                       .arg(b.variable.name, bindingMeaningKey(*b.meaning), b.byUse->reason,
                            stageName(b.byUse->stage))
                       .arg(b.byUse->line);
    return out;
}

Scene sceneForCapacity(const Scene &scene, std::optional<int> capacity, QString *note)
{
    const auto enabled = std::count_if(scene.lights.begin(), scene.lights.end(),
                                       [](const PointLight &l) { return l.enabled; });
    if (!capacity || enabled <= *capacity)
        return scene;
    Scene out = scene;
    int kept = 0;
    for (PointLight &l : out.lights)
        if (l.enabled && kept++ >= *capacity)
            l.enabled = false;
    *note =
        SceneStagesWords::tr("the shader takes %1 %2 (its light uniforms have room for no "
                             "more) and the scene has %3 enabled: checked with the first %1 alone")
            .arg(*capacity)
            .arg(*capacity == 1 ? SceneStagesWords::tr("light") : SceneStagesWords::tr("lights"))
            .arg(enabled);
    return out;
}

QString pngNameProblem(const QString &option, const QString &path)
{
    const QByteArray suffix = QFileInfo(path).suffix().toLower().toUtf8();
    if (suffix.isEmpty() || suffix == "png")
        return {};
    static const QList<QByteArray> others = [] {
        QList<QByteArray> formats = QImageWriter::supportedImageFormats();
        formats << "jpg"
                << "jpeg"
                << "gif"
                << "webp"
                << "tif"
                << "tiff"
                << "bmp"
                << "svg"
                << "exr"
                << "tga"
                << "heic"
                << "avif"
                << "jxl";
        return formats;
    }();
    if (!others.contains(suffix))
        return {};
    return SceneStagesWords::tr("%1 %2: PhongLab writes PNG images only; give a name that ends "
                                "in .png")
        .arg(option, path);
}

Result<> writePng(const QImage &image, const QString &path)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fail(SceneStagesWords::tr("cannot write: %1").arg(file.errorString()));
    if (!image.save(&file, "PNG")) {
        file.cancelWriting();
        return fail(SceneStagesWords::tr("PNG encoding failed"));
    }
    if (!file.commit())
        return fail(SceneStagesWords::tr("cannot write: %1").arg(file.errorString()));
    return {};
}

} // namespace phonglab::cli
