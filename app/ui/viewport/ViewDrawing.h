#pragma once
#include "core/view/DepthRange.h"
#include "render/draw/Renderer.h"

#include <vector>

namespace phonglab {

// How the view draws, beside the scene: the light markers, the headlight,
// what detail and leaving out lights may cost, and what the last frame
// drew. A view's settings, not the scene's (Viewport::currentScene() has
// no trace of them). Handed out by Viewport::drawing().
class ViewDrawing
{
public:
    virtual const Renderer::Options &renderOptions() const = 0;
    virtual void setShowLightMarkers(bool show) = 0;
    virtual bool showLightMarkers() const = 0;
    // The light whose marker is drawn highlighted (-1: none).
    virtual void setSelectedLight(int index) = 0;
    // A white light at the eye that follows the camera: the one light not in
    // world space; added only while fewer than kMaxLights are in use.
    virtual void setHeadlight(bool on) = 0;
    // What auto detail and, when `leaveOutLights`, leaving out unseen
    // lights may each change a pixel by (linear intensity; Renderer::Options).
    virtual void setReductionAllowance(double allowance, bool leaveOutLights) = 0;
    // How the last frame drew each object (level of detail, lights left out).
    virtual const std::vector<Renderer::ObjectDraw> &objectDraws() const = 0;
    // The near/far planes of the last frame (no GL call; any time).
    virtual const DepthRange &depthRange() const = 0;

protected:
    ~ViewDrawing() = default;
};

} // namespace phonglab
