#pragma once
#include "core/reference/ReferenceImage.h"
#include "core/scene/MeshData.h"
#include "core/scene/Scene.h"
#include "core/support/Result.h"

#include <QString>
#include <cstdint>
#include <memory>
#include <vector>

namespace phonglab {

// The sub-pixel precision to assume when the GPU's is unknown (no GL context
// to ask for GL_SUBPIXEL_BITS). OpenGL requires at least 4 bits; desktop
// GPUs and Mesa's llvmpipe/softpipe report 8, which is also what D3D-class
// hardware rasterises with (D3D10+ fixes 8 bits of sub-pixel precision). A
// smaller value than the real one only flags a few more pixels (a wider
// band), a larger one could miss some, so 8 is the usual value and not more.
inline constexpr int kDefaultSubpixelBits = 8;

// Pixels whose reference is ambiguous at the GPU's sub-pixel precision: where
// moving the pixel centre by 1/2^subpixelBits px changes coverage or makes the
// depth jump (occlusion edges inside the image, not only the outline). 1 = ambiguous.
//
// Why: a rasteriser snaps vertices to 1/2^GL_SUBPIXEL_BITS of a pixel, so an
// edge moves by up to half a step, and a pixel centre closer than that to an
// occluding edge (the outline, or one part of a mesh in front of another,
// like the default tree's tiers) may legitimately show either surface. The
// exact reference picks one; comparing a GPU pixel there with it measures
// the snapping, not the shading. Moving by a whole step is a margin of two.
//
// How: every pixel centre is ray-cast (geometry only, SceneDepthCaster) as
// is and moved by ±step along x and along y, where step = 2^-subpixelBits
// px (subpixelBits below OpenGL's minimum of 4 counts as 4). A covered
// pixel is ambiguous when one of the four moved centres is uncovered or its
// surface is not the continuation of the centre's one. Coverage is the
// reference's own: the mask is indexed like ReferenceImage (row 0 at the
// top) and its pixel centres are exactly raycastSceneMeshes()'s. An
// uncovered pixel is ambiguous when one moved centre is covered.
//
// "Continuation" is checked on the inverse depth 1/z, which is exactly affine
// in the image for any plane (the quantity a GPU interpolates linearly): per
// axis, the second difference 1/z(+step) + 1/z(-step) - 2/z(0) is zero on a
// plane, whatever the angle it is seen at, and tiny on a smooth or finely
// faceted surface, while across an occluding edge it is the jump in 1/z
// itself. A pixel is ambiguous where it exceeds 0.1 % of 1/z(0), i.e. a
// depth jump of more than about 0.1 % — the gaps between the tree's tiers
// are under 1 % (pixel (32, 114) at 256² lies 0.0008 px from a tier's
// edge). Checking the jump of z itself instead would also flag continuous
// surfaces seen at a grazing angle, whose depth changes fast but smoothly:
// that must not happen, those pixels are where the bench measures most.
// Missed: occluding gaps under 0.1 % of the depth, and a centre between two
// edges less than two steps apart whose jumps cancel exactly.
//
// objectMeshes as in raycastSceneMeshes() (one per object; null = the
// analytic surface of a builtin). A failure on bad input. Costs five
// shading-free casts per pixel, rows in parallel on all cores.
Result<std::vector<std::uint8_t>> ambiguousReferencePixels(
    const Scene &scene, const std::vector<std::shared_ptr<const MeshData>> &objectMeshes, int width,
    int height, int subpixelBits);

// The pixels a render is checked on against the reference: every pixel more
// than bandPx (Chebyshev) from an occluding contour (occludingContourPixels())
// or an ambiguous pixel (ambiguousReferencePixels()), which together are the
// silhouettes, the outline included. 1 = compared. What `phonglab bench` and
// `phonglab check` compare. A failure on bad input.
Result<std::vector<std::uint8_t>> awayFromSilhouettes(
    const ReferenceImage &reference, const Scene &scene,
    const std::vector<std::shared_ptr<const MeshData>> &objectMeshes, int bandPx);

} // namespace phonglab
