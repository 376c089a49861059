#pragma once
#include <EGL/egl.h>

#include <QString>

namespace phonglab::headless {

// An EGL display that needs no display server: the EGL device platform
// (a GPU, or Mesa's software device) or Mesa's surfaceless platform. Either
// draws only into framebuffer objects, which is all the headless commands
// need.
struct EglDisplayChoice {
    EGLDisplay display = EGL_NO_DISPLAY;
    QString problem; // why none could be opened, when display is EGL_NO_DISPLAY
};

// Tries $PHONGLAB_EGL_PLATFORM when set ("device" or "surfaceless"), else
// the device platform, then surfaceless. The display is initialized and
// bound to desktop OpenGL; a failure names every platform tried and why.
EglDisplayChoice openHeadlessEglDisplay();

// "EGL_BAD_ALLOC" and so on, for messages.
QString eglErrorName(EGLint error);

} // namespace phonglab::headless
