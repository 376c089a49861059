#pragma once
#include <QSurfaceFormat>

namespace phonglab {

// The context PhongLab renders with: OpenGL 3.3 core, 24-bit depth.
// `samples` > 0 asks for multisampling (the viewport); headless renders that
// are compared with the CPU reference use none.
QSurfaceFormat phonglabSurfaceFormat(int samples = 0);

} // namespace phonglab
