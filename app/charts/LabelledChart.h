#pragma once
#include "SpeedAccuracyChart.h"

#include <QPointF>
#include <QString>
#include <vector>

namespace phonglab {

// The one chart builder behind createSpeedAccuracyChart() and
// createLabelledChart(): axes, line + marker series with point labels, and
// optionally a Pareto front, all styled alike so every chart the bench
// writes looks the same.

struct ChartSpec {
    QString title;
    QString xTitle;
    QString yTitle; // e.g. "error: RMSE against the reference"
    QString yUnit;  // e.g. "8-bit steps"; the scale note joins it in parentheses
    std::vector<LabelledSeries> series;
    std::vector<QPointF> front; // raw (x, y), sorted by x; empty: no front
};

// A new chart (the caller owns it) for `spec`. The y axis turns logarithmic
// when the non-zero values span more than two decades, zeros then drawn on a
// floor the axis title names. Points with a NaN or infinite coordinate are
// left out.
QChart *buildChart(const ChartSpec &spec);

} // namespace phonglab
