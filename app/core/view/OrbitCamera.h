#pragma once
#include "Camera.h"

namespace phonglab {

// Turntable navigation around a Camera's target, for the interactive viewport.
// Pure math: no widgets, no GL. The camera's up vector is the turntable axis
// and never changes, nor do fovDeg, nearPlane and farPlane; only eye and
// target move. reset() returns exactly to the camera the scene was loaded with.
class OrbitCamera
{
public:
    OrbitCamera() = default;
    explicit OrbitCamera(const Camera &original);

    // A new scene: both the original and the current camera become `original`.
    void setOriginal(const Camera &original);
    void reset();

    const Camera &camera() const { return m_camera; }
    const Camera &original() const { return m_original; }

    // Moves the eye on the sphere around the target: yaw about the up axis,
    // pitch towards it (positive = look from higher up). Pitch stops short of
    // the poles, where the view would flip.
    void orbit(double yawDeg, double pitchDeg);

    // Slides eye and target together in the view plane. dx and dy are in
    // view heights at the target's distance (a drag of pixels / viewport
    // height keeps the target plane under the cursor); +dx moves the scene
    // right, +dy moves it down, as a mouse drag in widget coordinates does.
    void pan(double dx, double dy);

    // Multiplies the eye-target distance by `factor` (< 1 moves closer),
    // never closer than a margin beyond the near plane nor beyond the far one.
    void zoom(double factor);

    double distance() const;

    static constexpr double kPoleMarginDeg = 1.0;

private:
    glm::dvec3 upAxis() const;

    Camera m_original;
    Camera m_camera;
};

} // namespace phonglab
