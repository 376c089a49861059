#pragma once
#include "core/reference/ReferenceImage.h"
#include "core/reference/ShaderMistake.h"
#include "core/support/RgbImage.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace phonglab {

// Which classic mistake explains a wrong render. For each mistake the
// reference is rendered with that mistake made (ReferenceShader); a mistake
// explains the render as far as the render agrees with that image where
// either of them differs from the exact one.

struct MistakeFinding {
    ShaderMistake key = ShaderMistake::NormalMatrix;
    int form = 0; // which of the key's forms explains it best (MistakeVariant)
    // Mistakes that give the same image in this scene (reflect-incident and
    // view-vector always do): named beside `key` rather than guessed between.
    std::vector<ShaderMistake> also;
    double confidence = 0.0; // 0..1, the fraction of the difference it explains
    // Named by what the code does, not by the image: lighting in the vertex
    // shader is `gouraud` (core/program/VertexLighting), whatever it explains.
    bool fromCode = false;
};

// Real code breaks several rules at once: the smallest set of mistakes
// whose combined image explains the render (MistakeSets), one form of each
// key, in ShaderMistake's order.
struct MistakeSet {
    std::vector<MistakeVariant> variants;
    double explains = 0.0; // as MistakeFinding::confidence, of the combined image
    // The search reached kMaxMistakesTogether and the set still leaves a
    // part unexplained: more deviations than that would be needed.
    bool beyondLimit = false;
};

struct MistakeDiagnosis {
    qint64 differingPixels = 0; // compared pixels off the exact image by more than the tolerance
    std::vector<MistakeFinding>
        findings; // best first; those explaining at least kMinListedConfidence
    // Mistakes every form of which gives the exact image here.
    std::vector<ShaderMistake> undetectable;
    // The smallest set that explains the render; one variant where one
    // mistake does, empty where none was looked for (a pass) or found.
    MistakeSet together;
    // Differs, and no mistake explains at least kExplainedConfidence of it
    // (`unknown`: the heatmap is the answer).
    bool unexplained() const;
    // The set explains enough to be the answer (kExplainedConfidence, the
    // single mistakes' threshold); below it a set is only the closest one.
    bool togetherExplains() const;
};

// A program that lights per vertex is `gouraud` first, whatever the image:
// its Gouraud finding (or one made for it) goes to the front, marked
// fromCode, and the set of per-fragment mistakes is dropped.
void nameGouraudFromCode(MistakeDiagnosis &diagnosis);

inline constexpr double kExplainedConfidence = 0.5;
inline constexpr double kMinListedConfidence = 0.1;

// `yours` is the render (RGB, the reference's size); `exact` the reference;
// `mistaken` the reference with each mistake made; `compared` the pixels to
// check (1: compared; the silhouette band left out), one per pixel. A pixel
// matches another within `toleranceSteps` 8-bit steps in every channel.
// Where two mistakes give the same image, the one earlier in
// ShaderMistake's order is `key`. A key has one finding, its best form's. A render of another size than the
// reference differs everywhere and has no finding.
MistakeDiagnosis diagnoseMistakes(
    const RgbImage &yours, const ReferenceImage &exact,
    const std::vector<std::pair<MistakeVariant, ReferenceImage>> &mistaken,
    const std::vector<std::uint8_t> &compared, int toleranceSteps, const glm::dvec3 &background);

// The same on images already encoded as the GPU writes them
// (ReferenceImage::toImage()), which is all the diagnosis looks at: what a
// caller checking many renders against one reference keeps.
using MistakeImages = std::vector<std::pair<MistakeVariant, RgbImage>>;

// The pieces of the diagnosis MistakeSets shares. A pixel matches another
// within `steps` 8-bit steps in every channel.
bool withinSteps(const std::uint8_t *a, const std::uint8_t *b, int steps);
// The compared pixels where `image` is off `exact` by more than `steps`.
std::vector<std::uint8_t> differing(const RgbImage &image, const RgbImage &exact,
                                    const std::vector<std::uint8_t> &compared, int steps);
// Over the pixels where the render or the mistaken image differs from the
// exact one: the fraction where the mistaken image matches the render.
double explainedFraction(const RgbImage &yours, const std::vector<std::uint8_t> &yoursDiffers,
                         const RgbImage &mistaken, const std::vector<std::uint8_t> &mistakeDiffers,
                         const std::vector<std::uint8_t> &compared, int steps);
MistakeDiagnosis diagnoseMistakes(const RgbImage &yours, const RgbImage &exact,
                                  const MistakeImages &mistaken,
                                  const std::vector<std::uint8_t> &compared, int toleranceSteps);

} // namespace phonglab
