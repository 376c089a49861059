#pragma once
#include "core/scene/PointLight.h"
#include "core/view/Camera.h"

#include <QPointF>
#include <QSizeF>
#include <vector>

namespace phonglab {

// Screen ↔ world for dragging light markers in the viewport. Screen points
// are in widget coordinates (y down); `view` is the widget's size.

// The light whose marker is nearest `point`, within `radiusPx`; -1 if none.
int pickLight(const std::vector<PointLight> &lights, const Camera &camera, const QSizeF &view,
              const QPointF &point, double radiusPx);

// `position` moved so that it lands under `point`, keeping its depth: a move
// parallel to the view plane.
glm::dvec3 moveInViewPlane(const glm::dvec3 &position, const Camera &camera, const QSizeF &view,
                           const QPointF &point);

// `position` moved along the view direction by a vertical mouse move of
// `deltaYPx` (up: away from the eye), scaled by its distance to the eye.
glm::dvec3 moveAlongView(const glm::dvec3 &position, const Camera &camera, const QSizeF &view,
                         double deltaYPx);

} // namespace phonglab
