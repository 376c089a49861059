#include "ChartLabels.h"

#include <QGraphicsSimpleTextItem>
#include <QLineF>
#include <QtCharts/QChart>
#include <QtCharts/QLogValueAxis>
#include <QtCharts/QValueAxis>
#include <QtCharts/QXYSeries>

#include <algorithm>
#include <limits>

namespace phonglab {

namespace {

double overlapArea(const QRectF &a, const QRectF &b)
{
    const QRectF i = a.intersected(b);
    return i.isEmpty() ? 0.0 : i.width() * i.height();
}

std::vector<QRectF> markerSquares(QChart *chart,
                                  const std::vector<std::pair<QPointF, QAbstractSeries *>> &markers)
{
    std::vector<QRectF> squares;
    for (const auto &[value, series] : markers) {
        const QPointF p = chart->mapToPosition(value, series);
        squares.emplace_back(p.x() - 5, p.y() - 5, 10, 10);
    }
    return squares;
}

// Lines as small squares every few pixels along them.
std::vector<QRectF> lineDots(QChart *chart, const std::vector<QXYSeries *> &lines)
{
    std::vector<QRectF> dots;
    for (QXYSeries *line : lines) {
        const QList<QPointF> points = line->points();
        for (qsizetype i = 1; i < points.size(); ++i) {
            const QPointF a = chart->mapToPosition(points[i - 1], line);
            const QPointF b = chart->mapToPosition(points[i], line);
            const double length = QLineF(a, b).length();
            const int steps = std::clamp(int(length / 4.0), 1, 2000);
            for (int k = 0; k <= steps; ++k) {
                const QPointF p = a + (b - a) * (double(k) / steps);
                dots.emplace_back(p.x() - 1.5, p.y() - 1.5, 3, 3);
            }
        }
    }
    return dots;
}

// The first of the candidate spots around `p` (in order of preference) that
// covers least of what is taken, half as much of the lines, and twice as
// much of what lies outside the plot.
QRectF bestSpot(const QPointF &p, const QSizeF &s, const QRectF &plot,
                const std::vector<QRectF> &taken, const std::vector<QRectF> &dots)
{
    const double w = s.width(), h = s.height();
    const QPointF offsets[] = {
        {7, -h / 2},       // right
        {5, -h - 1},       // above right
        {-w / 2, -h - 6},  // above
        {5, 1},            // below right
        {-w / 2, 6},       // below
        {-7 - w, -h / 2},  // left
        {-5 - w, -h - 1},  // above left
        {-5 - w, 1},       // below left
        {12, -h / 2},      // further right
        {-w / 2, -h - 14}, // further above
        {-w / 2, 14},      // further below
        {-12 - w, -h / 2}, // further left
    };
    QRectF best;
    double bestScore = std::numeric_limits<double>::infinity();
    for (const QPointF &offset : offsets) {
        const QRectF r(p + offset, s);
        double score = 0;
        for (const QRectF &t : taken)
            score += overlapArea(r, t);
        for (const QRectF &t : dots)
            score += 0.5 * overlapArea(r, t);
        const double outside = w * h - overlapArea(r, plot);
        score += outside * 2.0;
        if (score < bestScore - 1e-9) {
            bestScore = score;
            best = r;
            if (score <= 0)
                break;
        }
    }
    return best;
}

} // namespace

void LabelPlacer::place() const
{
    const QRectF plot = chart->plotArea();
    if (plot.isEmpty())
        return;
    const QRectF inside = plot.adjusted(-0.5, -0.5, 0.5, 0.5);
    std::vector<QRectF> taken = markerSquares(chart, markers);
    const std::vector<QRectF> dots = lineDots(chart, lines);
    for (const PointLabel &label : labels) {
        const QPointF p = chart->mapToPosition(label.value, label.series);
        if (!inside.contains(p)) {
            label.item->setVisible(false);
            continue;
        }
        label.item->setVisible(true);
        const QRectF best = bestSpot(p, label.item->boundingRect().size(), plot, taken, dots);
        label.item->setPos(best.topLeft());
        taken.push_back(best);
    }
}

void keepLabelsPlaced(const std::shared_ptr<LabelPlacer> &placer, QAbstractAxis *xAxis,
                      QAbstractAxis *yAxis)
{
    QChart *chart = placer->chart;
    QObject::connect(chart, &QChart::plotAreaChanged, chart, [placer] { placer->place(); });
    for (QAbstractAxis *axis : {xAxis, yAxis}) {
        if (auto *value = qobject_cast<QValueAxis *>(axis))
            QObject::connect(value, &QValueAxis::rangeChanged, chart,
                             [placer] { placer->place(); });
        if (auto *log = qobject_cast<QLogValueAxis *>(axis))
            QObject::connect(log, &QLogValueAxis::rangeChanged, chart,
                             [placer] { placer->place(); });
    }
    placer->place();
}

} // namespace phonglab
