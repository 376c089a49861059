#include "core/check/ShaderCheck.h"
#include "core/support/Language.h"

#include "core/check/MistakeSets.h"
#include "core/program/VertexLighting.h"
#include "core/reference/PhongReference.h"
#include "core/reference/ReferenceEdges.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <tuple>

namespace phonglab {

Result<CheckReference> makeCheckReference(
    const Scene &scene, const std::vector<std::shared_ptr<const MeshData>> &objectMeshes, int width,
    int height, const std::function<bool(double)> &progress)
{
    // Casting is most of the work; shading each mistake is a fraction of it.
    const auto castProgress = [&](double f) { return !progress || progress(0.7 * f); };
    Result<SceneHits> hits = castSceneHits(scene, objectMeshes, width, height, castProgress);
    if (!hits)
        return fail(hits.error());
    CheckReference out;
    out.scene = scene;
    out.shader = idealShadingFor(scene.shading);
    out.background = scene.background;
    out.exact = shadeSceneHits(*hits, scene, out.shader);
    Result<std::vector<std::uint8_t>> compared =
        awayFromSilhouettes(out.exact, scene, objectMeshes, kCheckBandPx);
    if (!compared)
        return fail(compared.error());
    out.compared = std::move(*compared);
    for (std::size_t i = 0; i < out.compared.size(); ++i)
        out.compared[i] = out.compared[i] && out.exact.coverage[i];
    if (out.shader.shading == ReferenceShading::Phong) {
        // Every form of every mistake, each its own image.
        const std::vector<MistakeVariant> variants = allMistakeVariants();
        for (std::size_t m = 0; m < variants.size(); ++m) {
            if (progress && !progress(0.7 + 0.3 * double(m) / double(variants.size())))
                return fail(QStringLiteral("cancelled"));
            const ReferenceShader shader(ReferenceShading::Phong, variants[m]);
            ReferenceImage image = shadeSceneHits(*hits, scene, shader);
            out.mistaken.emplace_back(variants[m], image.toImage(out.background));
            if (variants[m].key == ShaderMistake::BackfaceSpecular)
                out.slide = std::move(image);
        }
    }
    out.exactImage = out.exact.toImage(out.background);
    out.undetectable = diagnoseMistakes(out.exactImage, out.exactImage, out.mistaken, out.compared,
                                        kDefaultCheckToleranceSteps)
                           .undetectable;
    out.hits = std::move(*hits);
    return out;
}

double CheckReport::badFraction() const
{
    return comparison.pixelsCompared > 0 ? double(badPixels) / double(comparison.pixelsCompared)
                                         : 0.0;
}

namespace {

// The reference checked against: the guarded one as made, or the slide's
// with the guarded image taking backface-specular's place among the mistakes
// (shaded once per reference, when a render first needs them).
struct CheckedAgainst {
    const ReferenceImage *exact;
    RgbImage exactImage;
    const MistakeImages *mistaken = nullptr;
};

MistakeImages slideMistakes(const CheckReference &reference);

CheckedAgainst checkedAgainst(const CheckReference &reference, PhongEquation equation)
{
    if (equation == PhongEquation::Guarded || reference.slide.color.empty())
        return {&reference.exact, reference.exactImage, &reference.mistaken};
    return {&reference.slide, reference.slide.toImage(reference.background), nullptr};
}

// Every mistake made in the slide's equation, as a student who writes the
// slide's form makes it (the reference holds them in the guarded one only):
// shaded from the kept hits the first time a render checked by the slide's
// equation fails, and kept (ShadedMistakes). Backface-specular's place
// goes to the guarded equation: against the slide's, that is its mistake.
MistakeImages slideMistakes(const CheckReference &reference)
{
    MistakeImages out;
    for (const auto &[variant, image] : reference.mistaken) {
        if (variant.key == ShaderMistake::BackfaceSpecular) {
            out.emplace_back(variant, reference.exactImage);
            continue;
        }
        ReferenceShader shader(ReferenceShading::Phong, variant);
        shader.equation = PhongEquation::Slide;
        out.emplace_back(
            variant,
            shadeSceneHits(reference.hits, reference.scene, shader).toImage(reference.background));
    }
    return out;
}

std::vector<int> errorSteps(const RgbImage &yours, const ReferenceImage &exact,
                            const std::vector<std::uint8_t> &compared)
{
    std::vector<int> out(exact.color.size(), -1);
    if (yours.width != exact.width || yours.height != exact.height)
        return out;
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (!compared[i])
            continue;
        int worst = 0;
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst,
                             std::abs(int(yours.pixel(i)[c]) - encodeChannel(exact.color[i][c])));
        out[i] = worst;
    }
    return out;
}

CheckReport checkAgainstEquation(const RgbImage &yours, const CheckReference &reference,
                                 int toleranceSteps, PhongEquation equation)
{
    CheckedAgainst against = checkedAgainst(reference, equation);
    CheckReport report;
    report.toleranceSteps = toleranceSteps;
    report.equation = equation;
    report.comparison =
        compareOutsideBand(yours, *against.exact, reference.background, 0, &reference.compared)
            .error;
    const std::vector<int> errors = errorSteps(yours, *against.exact, reference.compared);
    report.badPixels =
        std::count_if(errors.begin(), errors.end(), [&](int e) { return e > toleranceSteps; });
    if (report.comparison.pixelsCompared > 0) {
        const QPoint w = report.comparison.worstPixel;
        report.worstObject = reference.hits.at(w.x(), w.y()).object;
    }
    if (!report.comparable())
        return report;
    if (!report.passed()) {
        if (!against.mistaken)
            against.mistaken =
                &reference.shaded->slideMistakes([&] { return slideMistakes(reference); });
        report.diagnosis = diagnoseMistakes(yours, against.exactImage, *against.mistaken,
                                            reference.compared, toleranceSteps);
        if (reference.shader.shading == ReferenceShading::Phong)
            report.diagnosis.together = findMistakeSet(
                yours, against.exactImage, *against.mistaken, reference.compared, toleranceSteps,
                [&](const std::vector<MistakeVariant> &set) {
                    return reference.shaded->setImage(equation, set, [&] {
                        ReferenceShader shader(ReferenceShading::Phong, set);
                        shader.equation = equation;
                        return shadeSceneHits(reference.hits, reference.scene, shader)
                            .toImage(reference.background);
                    });
                });
    }
    // What cannot show is the scene's and the size's, whatever --tolerance
    // says: the mistakes whose image is the exact one at the default
    // tolerance (in the slide's equation they are the same ones). A larger
    // tolerance lets a mistake that shows pass; it does not hide it.
    report.diagnosis.undetectable = reference.undetectable;
    return report;
}

} // namespace

CheckReport checkRender(const RgbImage &yours, const CheckReference &reference, int toleranceSteps,
                        std::optional<PhongEquation> demanded)
{
    CheckReport report = checkAgainstEquation(yours, reference, toleranceSteps,
                                              demanded.value_or(PhongEquation::Guarded));
    report.silent = silentTerms(reference.scene);
    if (demanded || !report.comparable() || reference.slide.color.empty())
        return report;
    // Either equation is right: backface-specular is no mistake here. A
    // render that matches neither is checked by the one in which a mistake
    // explains with the fewest mistakes (a student writing the slide's form
    // makes the same mistakes in it, and backface-specular is none of
    // them), then the one explained best, then the one it is closer to.
    if (!report.passed()) {
        CheckReport slide =
            checkAgainstEquation(yours, reference, toleranceSteps, PhongEquation::Slide);
        const auto rank = [](const CheckReport &r) {
            const MistakeSet &set = r.diagnosis.together;
            const bool explained = set.explains >= kSetWellExplained;
            return std::tuple(explained ? 0 : 1, explained ? set.variants.size() : 0, -set.explains,
                              r.badPixels);
        };
        if (slide.passed() || rank(slide) < rank(report)) {
            slide.silent = std::move(report.silent);
            report = std::move(slide);
        }
    }
    std::erase(report.diagnosis.undetectable, ShaderMistake::BackfaceSpecular);
    return report;
}

void nameWhatTheCodeDoes(CheckReport &report, const QByteArray &vertex, const QByteArray &fragment)
{
    if (report.comparable() && !report.passed() && lightsPerVertex(vertex, fragment))
        nameGouraudFromCode(report.diagnosis);
}

RgbImage checkHeatmap(const RgbImage &yours, const CheckReference &reference,
                      PhongEquation equation)
{
    return errorHeatmap(yours, reference.exactOf(equation), 0, &reference.compared);
}

std::vector<int> checkErrorSteps(const RgbImage &yours, const CheckReference &reference,
                                 PhongEquation equation)
{
    return errorSteps(yours, reference.exactOf(equation), reference.compared);
}

namespace {

// The check's sentences, in the language the run speaks (core/support/Language).
struct CheckWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ShaderCheck)
};

QString psnrText(const ImageComparison &c)
{
    return std::isinf(c.psnr) ? QStringLiteral("PSNR ∞")
                              : CheckWords::tr("PSNR %1 dB").arg(sentenceNumber(c.psnr, 'f', 1));
}

// Several mistakes explain the render together, where no one does alone.
bool explainedBySeveral(const MistakeDiagnosis &d)
{
    return d.together.variants.size() > 1 && d.together.explains >= kExplainedConfidence;
}

QString setSummaries(const MistakeSet &set)
{
    QStringList parts;
    for (MistakeVariant v : set.variants)
        parts << QStringLiteral("%1: %2").arg(shaderMistakeKey(v.key), mistakeFormSummary(v));
    return parts.join(QStringLiteral("; "));
}

} // namespace

QString checkStatusLine(const CheckReport &report)
{
    const QString psnr = psnrText(report.comparison);
    if (report.passed()) {
        QString line = report.equation == PhongEquation::Slide
            ? CheckWords::tr("✓ %1 — the slide's equation").arg(psnr)
            : QStringLiteral("✓ %1").arg(psnr);
        QStringList silent;
        for (const SilentTerm &t : report.silent)
            silent << equationTermName(t.term);
        if (!silent.isEmpty())
            line +=
                CheckWords::tr(" — not checked here: %1").arg(silent.join(QStringLiteral(", ")));
        return line;
    }
    const MistakeDiagnosis &d = report.diagnosis;
    if (explainedBySeveral(d)) {
        QStringList keys;
        for (MistakeVariant v : d.together.variants)
            keys << shaderMistakeKey(v.key);
        return CheckWords::tr("✗ %1 — %2").arg(psnr, keys.join(QStringLiteral(" + ")));
    }
    if (d.unexplained() || d.findings.empty())
        return CheckWords::tr("✗ %1 — no classic mistake explains it").arg(psnr);
    const MistakeFinding &top = d.findings.front();
    QString line = CheckWords::tr("✗ %1 — %2").arg(psnr, shaderMistakeKey(top.key));
    for (ShaderMistake m : top.also)
        line += CheckWords::tr(" (or %1)").arg(shaderMistakeKey(m)); // its words are in the panel
    return line;
}

QString checkSummary(const CheckReport &report)
{
    const ImageComparison &c = report.comparison;
    const QString psnr = psnrText(c);
    if (report.passed())
        return CheckWords::tr("✓ matches the exact image (%1, max %2/255)")
            .arg(psnr)
            .arg(c.maxError);
    QString line = CheckWords::tr("✗ %1, max %2/255, %3 % of pixels off")
                       .arg(psnr)
                       .arg(c.maxError)
                       .arg(sentenceNumber(100.0 * report.badFraction(), 'f', 1));
    const MistakeDiagnosis &d = report.diagnosis;
    if (explainedBySeveral(d)) {
        line += CheckWords::tr(" — %1 mistakes together (%2 %): %3")
                    .arg(d.together.variants.size())
                    .arg(qRound(100.0 * d.together.explains))
                    .arg(setSummaries(d.together));
    } else if (d.unexplained()) {
        line += CheckWords::tr(" — unknown: no classic mistake explains it; see the heatmap");
    } else if (!d.findings.empty()) {
        const MistakeFinding &top = d.findings.front();
        QStringList keys{shaderMistakeKey(top.key)};
        for (ShaderMistake m : top.also)
            keys << shaderMistakeKey(m);
        line += CheckWords::tr(" — %1 (%2 %, %3): %4")
                    .arg(keys.join(CheckWords::tr(" or ")))
                    .arg(qRound(100.0 * top.confidence))
                    .arg(mistakeFormSummary({top.key, top.form}), shaderMistakeRule(top.key));
    }
    return line;
}

} // namespace phonglab
