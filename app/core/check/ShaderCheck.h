#pragma once
#include "core/check/MistakeDiagnosis.h"
#include "core/check/ShadedMistakes.h"
#include "core/check/SilentTerms.h"
#include "core/reference/ImageMetrics.h"
#include "core/reference/PhongEquation.h"
#include "core/reference/SceneHits.h"

#include <QByteArray>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace phonglab {

// `phonglab check` and the editor's check: a render checked against the
// exact reference of the same scene at the same size, and when it is off,
// which classic mistake explains it.

inline constexpr int kDefaultCheckToleranceSteps = 2; // max error 2/255

inline constexpr int kCheckBandPx = 2; // the render tests' silhouette band

// Everything a check needs that depends on the scene and the size alone, not
// on the shader: computed once, then any number of renders are checked
// against it, from any number of threads (it is read only, and `shaded`
// locks).
struct CheckReference {
    Scene scene; // as cast and shaded
    SceneHits hits;
    ReferenceShader shader; // the exact shading of the scene's method
    ReferenceImage exact;
    RgbImage exactImage; // exact, 8-bit as the GPU writes it
    // The slide's literal equation (PhongEquation::Slide) where it differs
    // from the guarded one: the backface-specular image. Empty for methods
    // other than Phong.
    ReferenceImage slide;
    // The reference with each classic mistake made, 8-bit (all the diagnosis
    // looks at, at 3 bytes a pixel), when the exact shading is Phong (the
    // mistakes are mistakes of Phong's equation); else empty.
    MistakeImages mistaken;
    std::vector<std::uint8_t> compared; // covered pixels away from every silhouette
    glm::dvec3 background{0.0};
    std::vector<ShaderMistake> undetectable; // mistakes whose image is the exact one here
    // What checks of renders shade beyond this: shared by the reference's
    // copies, safe to use from several threads at once.
    std::shared_ptr<ShadedMistakes> shaded = std::make_shared<ShadedMistakes>();

    // The exact image of `equation`: the slide's where there is one.
    const ReferenceImage &exactOf(PhongEquation equation) const
    {
        return equation == PhongEquation::Slide && !slide.color.empty() ? slide : exact;
    }
};

// Casts the scene once and shades it exactly and with every mistake. Every
// object is ray-cast as the triangle mesh the GPU draws (builtins included:
// objectMeshes has no null entry here), so a correct shader differs from the
// reference by float precision and rasterisation only. progress and
// cancelling as in castSceneHits().
Result<CheckReference> makeCheckReference(
    const Scene &scene, const std::vector<std::shared_ptr<const MeshData>> &objectMeshes, int width,
    int height, const std::function<bool(double)> &progress = {});

struct CheckReport {
    int toleranceSteps = kDefaultCheckToleranceSteps;
    ImageComparison comparison; // over the compared pixels
    qint64 badPixels = 0;       // compared pixels off by more than the tolerance
    int worstObject = -1;       // the scene object under comparison.worstPixel
    MistakeDiagnosis diagnosis;
    // The equation the render was checked by: the one it matched, else the
    // one demanded (guarded where none was).
    PhongEquation equation = PhongEquation::Guarded;
    // The terms zero in the whole scene (ks = 0 everywhere): a pass says
    // nothing about them.
    std::vector<SilentTerm> silent;

    // False when no pixel could be compared (nothing in view, or a tiny
    // image all silhouette): no verdict then, neither pass nor fail.
    bool comparable() const { return comparison.pixelsCompared > 0; }
    bool passed() const { return comparable() && comparison.maxError <= toleranceSteps; }
    double badFraction() const;
};

// Checked against the guarded equation, and where that fails against the
// slide's, unless `demanded` names one: the other is then a mistake
// (backface-specular).
CheckReport checkRender(const RgbImage &yours, const CheckReference &reference,
                        int toleranceSteps = kDefaultCheckToleranceSteps,
                        std::optional<PhongEquation> demanded = std::nullopt);
// What the program's text says that the image cannot: a program that
// lights per vertex (core/program/VertexLighting) is `gouraud` first, with
// its lines, whatever else its render shows. For every check of a render
// whose sources are known: `check`, `grade` and the window alike.
void nameWhatTheCodeDoes(CheckReport &report, const QByteArray &vertex, const QByteArray &fragment);

// |yours − exact| per pixel, as errorHeatmap() draws it: compared pixels
// from dark green (exact) through bright green (1/255) and yellow (4/255) to
// red (8/255 or more), the left-out silhouette band dark blue, uncovered
// pixels black.
// Against the exact image of `equation` (CheckReport::equation: the one the
// render was checked by).
RgbImage checkHeatmap(const RgbImage &yours, const CheckReference &reference,
                      PhongEquation equation = PhongEquation::Guarded);

// The largest channel error of each pixel in 8-bit steps; -1 where the pixel
// is not compared.
std::vector<int> checkErrorSteps(const RgbImage &yours, const CheckReference &reference,
                                 PhongEquation equation = PhongEquation::Guarded);

// "✓ matches the exact image (PSNR 58.2 dB, max 1/255)" or
// "✗ PSNR 21.4 dB, max 87/255, 12.0 % of pixels off — reflect-incident
// or view-vector (100 %): <the rule>" — everything in one line.
QString checkSummary(const CheckReport &report);
// The short form for a status bar: "✓ 58.2 dB — not checked here:
// specular", "✗ 21.4 dB — reflect-incident (or view-vector)", "✗ 26.8 dB —
// attenuation + halfway-vector": the mistakes' keys alone; their words are
// in the check's panel.
QString checkStatusLine(const CheckReport &report);

} // namespace phonglab
