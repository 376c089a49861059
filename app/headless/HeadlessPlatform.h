#pragma once
#include <QString>

namespace phonglab {

// The Qt platform that renders without a display server (headless/
// HeadlessIntegration): EGL on the device or Mesa's surfaceless platform.
inline constexpr char kHeadlessPlatformName[] = "phonglab-headless";

// Call before the Q(Gui)Application of a command that only renders
// offscreen, unless the user chose a platform (QT_QPA_PLATFORM): with no
// display server (neither DISPLAY nor WAYLAND_DISPLAY) the headless
// platform; with one, that display's platform and the headless one after
// it, for a display that cannot be reached (a stale DISPLAY over SSH).
void chooseCommandPlatform();

// Whether the running application uses the headless platform, and why it
// cannot make an OpenGL context (empty when it can or is not in use).
bool runsHeadless();
QString headlessGlProblem();

} // namespace phonglab
