#pragma once
#include "core/reference/ReferenceImage.h"

#include <QImage>
#include <QString>

namespace phonglab {

// render | reference | error heatmap side by side under a caption: the
// picture that shows where a method or a detail level breaks (see
// errorHeatmap() for the colours; the silhouette band is dark blue).
// `compared`: the bench's mask of pixels away from occluding contours
// (drawn as band where 0), or null.
QImage benchTriptych(const QImage &rendered, const ReferenceImage &reference,
                     const glm::dvec3 &background, int bandPx,
                     const std::vector<std::uint8_t> *compared, const QString &caption);

} // namespace phonglab
