#pragma once
#include <QImage>
#include <QSize>

namespace phonglab {

class Renderer;

// One frame of `renderer` drawn into a framebuffer of its own and read
// back: `samples` per pixel (0: none), resolved into a single-sample target
// to read. Needs the renderer's context current; a null image when the
// driver cannot make the framebuffer.
//
// Draw with the sample count of the framebuffer the program was warmed up
// for: the driver keeps a shader variant per framebuffer setup, and another
// one costs a compile on the calling thread (~80 ms on llvmpipe).
QImage drawIntoImage(Renderer &renderer, const QSize &pixelSize, int samples);

} // namespace phonglab
