#pragma once
#include "bench/BenchResult.h"
#include "core/support/Result.h"

#include <QColor>
#include <QSize>
#include <QString>
#include <algorithm>
#include <vector>

QT_BEGIN_NAMESPACE
class QChart;
QT_END_NAMESPACE

namespace phonglab {

// Speed against accuracy, drawn with Qt Charts. Everything here needs a
// QApplication (Qt Charts are QGraphicsWidgets) but never shows a window, so
// it runs under QT_QPA_PLATFORM=offscreen.

// The colour a shading method is always drawn in, on every chart: flat
// orange, gouraud green, blinn-phong purple, phong blue, anything else a
// fixed colour derived from its name.
QColor methodColor(const QString &method);

// One chart: frame time (x, ms) against error (y, RMSE in 8-bit steps; a log
// axis when the non-zero values span more than two decades, zeros then drawn
// on the axis floor, which the axis title names). One line + marker series
// per method, points ordered by detail and labelled "100 %", "25 %", ...
// (placed so they avoid each other and the markers, and kept in place when
// the chart is resized); the Pareto front of all the rows as a dashed grey
// step line with ringed markers ("Pareto front" in the legend). Rows whose
// time or RMSE is NaN are left out. The caller owns the chart.
QChart *createSpeedAccuracyChart(const std::vector<BenchRow> &rows, const QString &title);

// A grid of charts, one panel per (scene, light setup) in rows: scenes as
// grid rows (in order of first appearance), along each row that scene's
// light setups by count (scene's own lights after a synthetic setup of the
// same count), packed to the left; as many columns as the scene with the
// most setups. Written as PNG (device pixel ratio 1, panelSize × grid)
// and SVG (same size, 96 dpi), each through QSaveFile. An empty path skips that file. A failure when
// there is nothing to draw, no QApplication, or a file cannot be written.
Result<> writeSpeedAccuracyCharts(const std::vector<BenchRow> &rows, const QString &pngPath,
                                  const QString &svgPath, QSize panelSize = {640, 440});

// The general shape both charts above and the normal-method study use:
// named series of (x, y, point label) drawn as line + markers, labels placed
// to avoid each other. writeChartImages() renders one chart that is in no
// scene (it is resized to `size` and stays the caller's) like
// writeSpeedAccuracyCharts (PNG and/or SVG, QSaveFile).
struct LabelledPoint {
    double x = 0;
    double y = 0;
    QString label;
};
struct LabelledSeries {
    QString name;
    QColor color;
    std::vector<LabelledPoint> points; // drawn in this order
};
QChart *createLabelledChart(const std::vector<LabelledSeries> &series, const QString &title,
                            const QString &xTitle, const QString &yTitle);
Result<> writeChartImages(QChart *chart, const QString &pngPath, const QString &svgPath,
                          QSize size = {640, 440});

// The normal-method study (app/mesh/normals/NormalMethodStudy.h, NormalStudyRow:
// tessellation, method, triangles, ms, maxAngleDeg, meanAngleDeg): time (x,
// ms) against mean angular error (y, degrees), one series per tessellation
// with its points labelled by method. A template over the row type so this
// header does not depend on the mesh study; any range of rows with those
// fields will do. Written like writeChartImages().
Result<> writeNormalStudySeriesChart(std::vector<LabelledSeries> series, const QString &pngPath,
                                     const QString &svgPath, QSize size = {640, 440});
template <typename NormalStudyRows>
Result<> writeNormalStudyChart(const NormalStudyRows &rows, const QString &pngPath,
                               const QString &svgPath, QSize size = {640, 440})
{
    std::vector<LabelledSeries> series;
    for (const auto &row : rows) {
        auto it = std::find_if(series.begin(), series.end(),
                               [&](const LabelledSeries &s) { return s.name == row.tessellation; });
        if (it == series.end()) {
            series.push_back(LabelledSeries{row.tessellation, QColor(), {}});
            it = series.end() - 1;
        }
        it->points.push_back(LabelledPoint{double(row.ms), double(row.meanAngleDeg), row.method});
    }
    return writeNormalStudySeriesChart(std::move(series), pngPath, svgPath, size);
}

} // namespace phonglab
