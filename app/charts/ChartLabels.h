#pragma once

#include <QPointF>
#include <memory>
#include <vector>

QT_BEGIN_NAMESPACE
class QAbstractAxis;
class QAbstractSeries;
class QChart;
class QGraphicsSimpleTextItem;
class QXYSeries;
QT_END_NAMESPACE

namespace phonglab {

// Point labels on a chart ("100 %", "flat", ...) as plain text items rather
// than Qt Charts' own point labels, which are drawn on top of each other and
// of the markers. Each is placed next to its point where it hits no other
// label and no marker, and placed again after every layout (resize, zoom),
// since the point's position in the scene moves with the plot area.

struct PointLabel {
    QGraphicsSimpleTextItem *item = nullptr; // a child of the chart
    QPointF value;                           // the point, in series values
    QAbstractSeries *series = nullptr;       // maps `value` to the scene
};

struct LabelPlacer {
    QChart *chart = nullptr;
    std::vector<PointLabel> labels; // placed in this order; earlier ones win
    std::vector<std::pair<QPointF, QAbstractSeries *>> markers; // obstacles
    std::vector<QXYSeries *> lines; // lines are lighter obstacles than markers and labels

    // Moves every label to its best spot for the current plot area; labels
    // whose point is outside the plot area are hidden.
    void place() const;
};

// Places the labels now and again whenever the chart's plot area or either
// axis range changes (a QValueAxis or QLogValueAxis; others are not
// followed). The connections hold `placer` and end with the chart.
void keepLabelsPlaced(const std::shared_ptr<LabelPlacer> &placer, QAbstractAxis *xAxis,
                      QAbstractAxis *yAxis);

} // namespace phonglab
