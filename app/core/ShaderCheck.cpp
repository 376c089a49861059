#include "ShaderCheck.h"

#include "PhongReference.h"
#include "ReferenceEdges.h"

#include <algorithm>
#include <cmath>

namespace phonglab {

namespace {

std::vector<ShaderMistake> allMistakes()
{
    std::vector<ShaderMistake> out;
    for (const QString &key : shaderMistakeKeys())
        out.push_back(*shaderMistakeFromKey(key));
    return out;
}

} // namespace

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
        const std::vector<ShaderMistake> mistakes = allMistakes();
        for (std::size_t m = 0; m < mistakes.size(); ++m) {
            if (progress && !progress(0.7 + 0.3 * double(m) / double(mistakes.size())))
                return fail(QStringLiteral("cancelled"));
            const ReferenceShader shader(ReferenceShading::Phong, mistakes[m]);
            out.mistaken.emplace_back(mistakes[m],
                                      shadeSceneHits(*hits, scene, shader).toImage(out.background));
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

CheckReport checkRender(const RgbImage &yours, const CheckReference &reference, int toleranceSteps)
{
    CheckReport report;
    report.toleranceSteps = toleranceSteps;
    report.comparison =
        compareOutsideBand(yours, reference.exact, reference.background, 0, &reference.compared)
            .error;
    const std::vector<int> errors = checkErrorSteps(yours, reference);
    report.badPixels =
        std::count_if(errors.begin(), errors.end(), [&](int e) { return e > toleranceSteps; });
    if (report.comparison.pixelsCompared > 0) {
        const QPoint w = report.comparison.worstPixel;
        report.worstObject = reference.hits.at(w.x(), w.y()).object;
    }
    if (!report.comparable())
        return report;
    if (!report.passed())
        report.diagnosis = diagnoseMistakes(yours, reference.exactImage, reference.mistaken,
                                            reference.compared, toleranceSteps);
    else if (toleranceSteps != kDefaultCheckToleranceSteps)
        report.diagnosis.undetectable =
            diagnoseMistakes(reference.exactImage, reference.exactImage, reference.mistaken,
                             reference.compared, toleranceSteps)
                .undetectable;
    else
        report.diagnosis.undetectable = reference.undetectable;
    return report;
}

RgbImage checkHeatmap(const RgbImage &yours, const CheckReference &reference)
{
    return errorHeatmap(yours, reference.exact, 0, &reference.compared);
}

std::vector<int> checkErrorSteps(const RgbImage &yours, const CheckReference &reference)
{
    const ReferenceImage &exact = reference.exact;
    std::vector<int> out(exact.color.size(), -1);
    if (yours.width != exact.width || yours.height != exact.height)
        return out;
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (!reference.compared[i])
            continue;
        int worst = 0;
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst,
                             std::abs(int(yours.pixel(i)[c]) - encodeChannel(exact.color[i][c])));
        out[i] = worst;
    }
    return out;
}

namespace {

QString psnrText(const ImageComparison &c)
{
    return std::isinf(c.psnr) ? QStringLiteral("PSNR ∞")
                              : QStringLiteral("PSNR %1 dB").arg(c.psnr, 0, 'f', 1);
}

} // namespace

QString checkStatusLine(const CheckReport &report)
{
    const QString psnr = psnrText(report.comparison);
    if (report.passed())
        return QStringLiteral("✓ %1").arg(psnr);
    const MistakeDiagnosis &d = report.diagnosis;
    if (d.unexplained() || d.findings.empty())
        return QStringLiteral("✗ %1 — no classic mistake explains it: see the heatmap").arg(psnr);
    const MistakeFinding &top = d.findings.front();
    QString line = QStringLiteral("✗ %1 — %2: %3")
                       .arg(psnr, shaderMistakeKey(top.key), shaderMistakeSummary(top.key));
    for (ShaderMistake m : top.also)
        line += QStringLiteral(" (or %1)").arg(shaderMistakeKey(m)); // its words are in the tooltip
    return line;
}

QString checkSummary(const CheckReport &report)
{
    const ImageComparison &c = report.comparison;
    const QString psnr = psnrText(c);
    if (report.passed())
        return QStringLiteral("✓ matches the exact image (%1, max %2/255)")
            .arg(psnr)
            .arg(c.maxError);
    QString line = QStringLiteral("✗ %1, max %2/255, %3 % of pixels off")
                       .arg(psnr)
                       .arg(c.maxError)
                       .arg(100.0 * report.badFraction(), 0, 'f', 1);
    const MistakeDiagnosis &d = report.diagnosis;
    if (d.unexplained()) {
        line += QStringLiteral(" — unknown: no classic mistake explains it; see the heatmap");
    } else if (!d.findings.empty()) {
        const MistakeFinding &top = d.findings.front();
        QStringList keys{shaderMistakeKey(top.key)};
        for (ShaderMistake m : top.also)
            keys << shaderMistakeKey(m);
        line += QStringLiteral(" — %1 (%2 %): %3")
                    .arg(keys.join(QStringLiteral(" or ")))
                    .arg(qRound(100.0 * top.confidence))
                    .arg(shaderMistakeRule(top.key));
    }
    return line;
}

} // namespace phonglab
