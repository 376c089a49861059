#pragma once
#include "JavaScriptFinding.h"
#include "PageCapture.h"
#include "core/program/ShaderBindings.h"

#include <vector>

namespace phonglab {

// The matrices and the light a page sent, against each other, for each
// program drawn in the captured frame:
//  - the normal matrix against the inverse transpose of the model-view
//    sent (up to a factor: the shader normalises), and what it is instead:
//    the transpose (Angel's shadedSphere2 sends it: the inverse of the
//    rotation), the inverse, the model-view itself, or the model's alone;
//  - the model-view against view·model, and the model-view-projection
//    against projection·model-view, where the page sends those too;
//  - a light position sent with w = 0 (a direction, not a place);
//  - a product sent beside its factors (ambientProduct beside the light's
//    ambient and ka) that is not theirs.
// Keys: normal-matrix-right, normal-matrix-transpose,
// normal-matrix-inverse, normal-matrix-model-view, normal-matrix-model,
// normal-matrix-other, matrices-disagree, light-w-zero, product-not-of-its-factors.
std::vector<JavaScriptFinding> checkPageMatrices(const PageCapture &capture,
                                                 const ExplicitBindings &explicitBindings = {});

} // namespace phonglab
