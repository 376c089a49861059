#pragma once
#include "core/check/MistakeDiagnosis.h"

#include <functional>
#include <vector>

namespace phonglab {

// Real course code breaks several of the equation's rules at once (Blinn's
// halfway vector and no attenuation and no ambient term), and no single
// mistake's image explains its render. The smallest set of mistakes, up to
// kMaxMistakesTogether, whose combined image explains it, found by
// bringing the set's image ever closer to the render (the sum of squared
// channel differences over the compared pixels):
//  - the set starts with the mistake whose image comes closest;
//  - each step estimates, without shading, every set one step away (one
//    mistake added or put in place of another form of its key, or two
//    added: terms that cancel each other in places, no ambient and no
//    attenuation, show only together) by adding each mistake's own change
//    from the exact image to the set's image, on a sample of the pixels;
//  - the few that come closest are shaded for real, and the closest is taken
//    while it takes at least kSetDistanceCut off the distance and the set
//    explains less than kSetExplains.
// A render one mistake explains costs no shading at all: its set is that
// mistake. Gouraud and per-face change where the equation is evaluated and
// are named alone, never in a set.

inline constexpr int kMaxMistakesTogether = 4;
inline constexpr double kSetExplains = 0.999;
inline constexpr double kSetDistanceCut = 0.3;
// A set explaining this much is taken as the answer when two equations'
// sets are compared (ShaderCheck): then the smaller set wins.
inline constexpr double kSetWellExplained = 0.95;

// The combined image of a set, 8-bit as the GPU writes it.
using ShadeMistakes = std::function<RgbImage(const std::vector<MistakeVariant> &)>;

MistakeSet findMistakeSet(const RgbImage &yours, const RgbImage &exact,
                          const MistakeImages &singles, const std::vector<std::uint8_t> &compared,
                          int toleranceSteps, const ShadeMistakes &shade);

// "halfway-vector + attenuation/1": the set's keys, for tables and logs.
QString mistakeSetName(const MistakeSet &set);
// The keys alone, space-separated: grades.csv's `mistakes`.
QString mistakeSetKeys(const MistakeSet &set);

} // namespace phonglab
