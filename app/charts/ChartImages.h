#pragma once
#include "core/support/Result.h"

#include <QSize>
#include <QString>
#include <vector>

QT_BEGIN_NAMESPACE
class QChart;
class QGraphicsScene;
QT_END_NAMESPACE

namespace phonglab {

// Turning charts into files: a QGraphicsScene of charts rendered to PNG and
// SVG, each written through QSaveFile so a failed run leaves no half-written
// image behind. writeChartImages() (declared in SpeedAccuracyChart.h) is
// defined here on top of these.

// Success when a QApplication exists. Qt Charts are QGraphicsWidgets and
// need one, so every public entry point checks this first and reports a
// missing one as an error.
Result<> haveApplication();

// Lays out every chart in the scene (layouts are otherwise deferred to the
// event loop) so the point labels sit where they will be drawn.
void settleLayouts(const std::vector<QChart *> &charts);

// Renders the (0, 0, size) part of `scene` on white to PNG (device pixel
// ratio 1) and SVG (same size, 96 dpi, `title` as its title). An empty path
// skips that file; both empty is an error. Both files are opened before
// anything is drawn, so a bad path writes nothing.
Result<> renderScene(QGraphicsScene &scene, const QSize &size, const QString &pngPath,
                     const QString &svgPath, const QString &title);

} // namespace phonglab
