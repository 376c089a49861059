#pragma once
#include "PageCapture.h"
#include "core/check/ShaderCheck.h"
#include "core/scene/MeshData.h"
#include "core/scene/Scene.h"
#include "core/support/Result.h"
#include "core/support/RgbImage.h"

#include <memory>
#include <vector>

namespace phonglab {

// The student's own scene, read out of a page's capture, so that its exact
// image can be compared with the browser's pixels: each draw of the program
// that lights is an object (its mesh from the buffers), the camera comes
// from the projection sent, the lights and material from the uniforms,
// their meanings found as for a static check (by name, then by use).
//
// It is built in eye coordinates: every mesh is moved by the model-view
// the page sent (or view · model), a light in world coordinates by the
// view, and the camera sits at the origin looking down -z, as the
// projection expects. Lighting in eye coordinates is lighting in world
// coordinates where the view is rigid, so this is the page's own scene.
//
// A failure says why the scene cannot be read, in a sentence: the camera
// is not a symmetric perspective, the page sends only the product of its
// matrices, a uniform that changes the image means nothing PhongLab knows,
// two draws disagree on the lights. Nothing is checked then.
struct PageScene {
    Scene scene;
    std::vector<std::shared_ptr<const MeshData>> meshes; // one per scene object
    int program = 0;                                     // the program whose draws it holds
};

Result<PageScene> pageSceneOf(const PageCapture &capture);

// The browser's frame against the exact image of the page's own scene
// (with snapping allowed, below), and what the program's text says; why
// not where the scene cannot be read.
struct PageSceneCheck {
    CheckReport report;
    RgbImage exact;   // the own scene's exact image, 8-bit
    RgbImage heatmap; // the browser's frame against it (checkHeatmap)
};
Result<PageSceneCheck> checkPageScene(const PageCapture &capture);

// The browser's frame as the check compares images: RGB, row 0 on top.
RgbImage browserFrame(const PageCapture &capture);

// The browser's frame with what its rasteriser's precision explains taken
// out, for a comparison with the exact image: SwiftShader snaps vertices to
// 1/16 pixel, which moves every interpolated value by up to 1/32 pixel. A
// pixel may differ from the exact one by its gradient there (the largest
// step to a neighbour) over 16 more than the check's tolerance; by that
// much it is moved toward the exact value. A mistake moves far more.
inline constexpr int kSnapSubpixels = 16;
RgbImage withSnappingAllowed(const RgbImage &browser, const RgbImage &exact);

} // namespace phonglab
