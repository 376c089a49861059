#pragma once
#include <QByteArray>

namespace phonglab {

// Whether a program evaluates the illumination equation in its vertex
// shader and hands the fragment shader a colour to interpolate (Gouraud
// shading, as Angel & Shreiner's shadedCube does): the vertex stage calls
// dot, pow or reflect, and the fragment stage none of them, through no
// `flat` output (that is flat shading: per-face). Read from the
// text alone, so that the check names `gouraud` for what the code does,
// whatever else the image shows (the per-fragment mistakes' images cannot
// explain a colour interpolated across a face).
bool lightsPerVertex(const QByteArray &vertex, const QByteArray &fragment);

} // namespace phonglab
