#pragma once
#include "PageCapture.h"

#include <QString>

#include <optional>

namespace phonglab {

// Whether a captured draw reads only bytes its buffers hold. A capture is
// a file anyone can hand PhongLab (check --capture), and a desktop driver
// does not bound-check a draw the way WebGL does: a draw that would read
// past a buffer is refused before it reaches the driver.

// Bytes of one component of an attribute (FLOAT: 4); 0 for an unknown type.
int componentBytes(unsigned glType);
// Bytes between two vertices' values: the stride, or the packed size.
qint64 attributeStride(const CapturedAttribute &attribute);
// The largest vertex index the draw reads (its first + count - 1, or the
// largest index in its index buffer, primitive restart left out); -1 when
// it reads none; nullopt with `problem` set when the index buffer is short.
std::optional<qint64> largestVertex(const PageCapture &capture, const CapturedOp &draw,
                                    QString *problem);
// Empty when the draw fits its buffers; else why not, in words.
QString drawOutOfBounds(const PageCapture &capture, const CapturedOp &draw);

} // namespace phonglab
