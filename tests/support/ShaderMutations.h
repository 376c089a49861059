#pragma once
#include "core/reference/PhongEquation.h"
#include "core/reference/ShaderMistake.h"
#include "core/support/RgbImage.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/program/ShaderSource.h"

#include <vector>

// The shipped Phong shaders (shaders/phong.vert, phong.frag) with one classic
// mistake made in them, the way a student makes it: what the confusion-matrix
// tests hand to the check, and the docs' pictures show. Each mutation is a
// textual replacement that must match the shipped text exactly, so a change
// of the shipped shaders that would silently void a mutation aborts instead.
// `gouraud` is the shipped gouraud.vert/.frag: the whole equation per vertex.
namespace phonglab::test {

struct ShaderPair {
    ShaderSource vertex;
    ShaderSource fragment;
};

ShaderPair shippedPhong();
ShaderPair withMistake(ShaderMistake mistake);
// The mistake in one of its forms (MistakeForm), as a student writes it;
// form 0 is withMistake(key).
ShaderPair withMistake(MistakeVariant variant);
// The same, written in the slide's equation (no N·L guard on the highlight,
// the diffuse term clamped) where `equation` says so; not for the mistakes
// that are about that guard (negative-light, backface-specular) or that
// replace the whole shader (gouraud).
ShaderPair withMistake(MistakeVariant variant, PhongEquation equation);
// Several mistakes made in one pair, as real code makes them (not gouraud
// or per-face, which replace the whole pair).
ShaderPair withMistakes(const std::vector<MistakeVariant> &set);

// The pair built in `offscreen`'s renderer and one frame of its scene drawn
// at `size`; a pair that does not compile is the test's own bug (qFatal).
RgbImage drawPair(OffscreenRenderer &offscreen, const ShaderPair &pair, QSize size);

} // namespace phonglab::test
