#pragma once
#include <QString>

namespace phonglab {

// The Qt platform that renders without a display server (headless/
// HeadlessIntegration): EGL on the device or Mesa's surfaceless platform.
inline constexpr char kHeadlessPlatformName[] = "phonglab-headless";

// Call before the Q(Gui)Application of a command that only renders
// offscreen: when the user chose no platform (QT_QPA_PLATFORM) and there is
// no display server (neither DISPLAY nor WAYLAND_DISPLAY), the headless
// platform is chosen. With a display the usual platform stays, as before.
void useHeadlessPlatformWithoutDisplay();

// Whether the running application uses the headless platform, and why it
// cannot make an OpenGL context (empty when it can or is not in use).
bool runsHeadless();
QString headlessGlProblem();

} // namespace phonglab
