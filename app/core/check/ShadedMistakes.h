#pragma once
#include "core/check/MistakeDiagnosis.h"
#include "core/reference/PhongEquation.h"
#include "core/support/RgbImage.h"

#include <functional>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

namespace phonglab {

// The images of mistakes a check shades beyond the reference's own (every
// mistake in the slide's equation, and the sets the set search tries), kept
// with the reference they were shaded from: a class makes the same mistakes
// over and over, and `grade` checks every render of a scene against one
// reference, on several threads at once. Each image is shaded once; every
// caller after the first gets the same one.
class ShadedMistakes
{
public:
    using Shade = std::function<RgbImage()>;

    // Every mistake in the slide's equation, made by `shadeAll` the first
    // time it is asked for.
    const MistakeImages &slideMistakes(const std::function<MistakeImages()> &shadeAll);
    // The image of `set` in `equation`, shaded by `shade` unless kept. Past
    // kMaxKeptSets images the cache keeps no more (shading them each time),
    // which bounds its memory at kMaxKeptSets images of the check's size.
    RgbImage setImage(PhongEquation equation, const std::vector<MistakeVariant> &set,
                      const Shade &shade);

    static constexpr std::size_t kMaxKeptSets = 48;

private:
    std::once_flag m_slideOnce;
    MistakeImages m_slide;
    std::mutex m_setsMutex;
    std::map<std::pair<PhongEquation, std::vector<MistakeVariant>>, RgbImage> m_sets;
};

} // namespace phonglab
