#include "LabelledChart.h"
#include "ChartLabels.h"
#include "core/support/Language.h"

#include <QCoreApplication>
#include <QGraphicsSimpleTextItem>
#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QLogValueAxis>
#include <QtCharts/QScatterSeries>
#include <QtCharts/QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct LabelledChartWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::LabelledChart)
};

namespace {

// How the y values are drawn: linear from 0, or log10 with zeros (and
// anything else not positive) lifted onto a floor one step below the data.
struct YScale {
    bool log = false;
    double floor = 0; // log only: where zeros are drawn
    double min = 0;
    double max = 1;
    bool hasZero = false;

    double map(double y) const { return log && y <= 0 ? floor : y; }
};

YScale chooseYScale(const std::vector<double> &values)
{
    YScale scale;
    double minPositive = std::numeric_limits<double>::infinity();
    double maxValue = 0;
    for (double v : values) {
        if (!std::isfinite(v))
            continue;
        if (v > 0)
            minPositive = std::min(minPositive, v);
        else
            scale.hasZero = true;
        maxValue = std::max(maxValue, v);
    }
    if (std::isfinite(minPositive) && maxValue / minPositive > 100.0) {
        scale.log = true;
        double floor = std::pow(10.0, std::floor(std::log10(minPositive)));
        if (scale.hasZero && floor >= minPositive * 0.999)
            floor /= 10.0;
        scale.floor = floor;
        // A little room below the floor and above the largest value, so no
        // point sits on the frame and the floor's own label shows.
        scale.min = floor / 1.6;
        scale.max = std::pow(10.0, std::ceil(std::log10(maxValue * 1.25)));
        if (scale.max <= scale.min)
            scale.max = scale.min * 10.0;
    } else {
        scale.min = 0;
        scale.max = maxValue > 0 ? maxValue * 1.12 : 1.0;
    }
    return scale;
}

QString trimmedNumber(double v)
{
    return sentenceNumber(v, 'g', 6);
}

QFont sizedFont(QFont font, double pointSize, bool bold = false)
{
    font.setPointSizeF(pointSize);
    font.setBold(bold);
    return font;
}

// An empty chart with the look every chart of the bench has.
QChart *styledChart(const QString &title)
{
    auto *chart = new QChart;
    chart->setLocalizeNumbers(true); // axis labels write numbers as the sentences do
    chart->setLocale(sentenceLocale());
    chart->setTitle(title);
    chart->setTitleFont(sizedFont(chart->titleFont(), 11, true));
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->setDropShadowEnabled(false);
    chart->setBackgroundRoundness(0);
    chart->setMargins(QMargins(6, 4, 10, 4));
    chart->legend()->setAlignment(Qt::AlignBottom);
    chart->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries);
    chart->legend()->setFont(sizedFont(chart->legend()->font(), 8.5));
    return chart;
}

// The x axis over `xs`, from 0 or a little below their least, with room on
// the right for labels.
QValueAxis *xAxisFor(const std::vector<double> &xs, const QString &title)
{
    auto *axis = new QValueAxis;
    axis->setTitleText(title);
    axis->setTitleFont(sizedFont(axis->titleFont(), 9));
    axis->setLabelsFont(sizedFont(axis->labelsFont(), 8));
    axis->setLabelFormat(QStringLiteral("%.6g")); // localized labels need a precision
    double xMin = 0, xMax = 1;
    if (!xs.empty()) {
        xMin = *std::min_element(xs.begin(), xs.end());
        xMax = *std::max_element(xs.begin(), xs.end());
        const double span = xMax - xMin;
        const double pad = span > 0 ? span * 0.1 : std::max(std::abs(xMax) * 0.1, 0.1);
        xMin = std::max(0.0, xMin - pad);
        xMax = xMax + pad * 1.5;
    }
    axis->setRange(xMin, xMax);
    axis->setTickCount(6);
    axis->applyNiceNumbers();
    return axis;
}

// The y axis of `scale`: logarithmic where chooseYScale() chose it, its
// title saying so and where 0 is drawn.
QAbstractAxis *yAxisFor(const YScale &scale, const ChartSpec &spec)
{
    QAbstractAxis *yAxis = nullptr;
    QStringList notes;
    if (!spec.yUnit.isEmpty())
        notes << spec.yUnit;
    if (scale.log) {
        auto *axis = new QLogValueAxis;
        axis->setBase(10);
        axis->setLabelFormat(QStringLiteral("%.6g")); // localized labels need a precision
        axis->setMinorTickCount(8);
        axis->setMinorGridLineColor(QColor(238, 238, 238));
        axis->setRange(scale.min, scale.max);
        notes << (scale.hasZero
                      ? LabelledChartWords::tr("log; 0 drawn at %1").arg(trimmedNumber(scale.floor))
                      : QStringLiteral("log"));
        yAxis = axis;
    } else {
        auto *axis = new QValueAxis;
        axis->setLabelFormat(QStringLiteral("%.6g")); // localized labels need a precision
        axis->setRange(scale.min, scale.max);
        axis->setTickCount(6);
        axis->applyNiceNumbers();
        yAxis = axis;
    }
    yAxis->setTitleText(notes.isEmpty() ? spec.yTitle
                                        : QStringLiteral("%1 (%2)").arg(
                                            spec.yTitle, notes.join(QStringLiteral(", "))));
    yAxis->setTitleFont(sizedFont(yAxis->titleFont(), 9));
    yAxis->setLabelsFont(sizedFont(yAxis->labelsFont(), 8));
    return yAxis;
}

// A chart with its axes: what a series is added to.
struct ChartAxes {
    QChart *chart = nullptr;
    QValueAxis *x = nullptr;
    QAbstractAxis *y = nullptr;
    YScale scale;

    void attach(QAbstractSeries *series) const
    {
        chart->addSeries(series);
        series->attachAxis(x);
        series->attachAxis(y);
    }
    void hideFromLegend(QAbstractSeries *series) const
    {
        for (QLegendMarker *marker : chart->legend()->markers(series))
            marker->setVisible(false);
    }
};

// One method's points: a line through them, markers on them, and each
// point's label for the placer to keep beside it.
void addSeries(const ChartAxes &axes, const LabelledSeries &s, LabelPlacer &placer)
{
    auto *line = new QLineSeries;
    line->setName(s.name);
    line->setPen(QPen(s.color, 1.8));
    auto *markers = new QScatterSeries;
    markers->setName(s.name);
    markers->setMarkerShape(QScatterSeries::MarkerShapeCircle);
    markers->setMarkerSize(8);
    markers->setColor(s.color);
    markers->setBorderColor(s.color.darker(140));
    std::vector<const LabelledPoint *> drawn;
    for (const LabelledPoint &p : s.points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            continue;
        const QPointF value(p.x, axes.scale.map(p.y));
        line->append(value);
        markers->append(value);
        drawn.push_back(&p);
    }
    axes.attach(line);
    axes.attach(markers);
    axes.hideFromLegend(line);
    placer.lines.push_back(line);
    for (const QPointF &value : markers->points())
        placer.markers.emplace_back(value, markers);
    const QFont labelFont = sizedFont(axes.chart->titleFont(), 7.5, false);
    for (std::size_t index = 0; index < drawn.size(); ++index) {
        if (drawn[index]->label.isEmpty())
            continue;
        auto *item = new QGraphicsSimpleTextItem(drawn[index]->label, axes.chart);
        item->setFont(labelFont);
        item->setBrush(s.color.darker(150));
        item->setZValue(1000);
        placer.labels.push_back({item, markers->at(int(index)), markers});
    }
}

// The front after the methods, so the legend lists it last: a dashed step
// line (everything above and right of it is beaten) and rings.
void addFront(const ChartAxes &axes, const std::vector<QPointF> &front, LabelPlacer &placer)
{
    const QColor frontColor(110, 110, 110);
    auto *step = new QLineSeries;
    step->setName(LabelledChartWords::tr("Pareto front"));
    step->setPen(QPen(frontColor, 1.4, Qt::DashLine));
    for (size_t i = 0; i < front.size(); ++i) {
        const QPointF p(front[i].x(), axes.scale.map(front[i].y()));
        if (i > 0)
            step->append(p.x(), axes.scale.map(front[i - 1].y()));
        step->append(p);
    }
    axes.attach(step);
    placer.lines.push_back(step);

    auto *rings = new QScatterSeries;
    rings->setName(LabelledChartWords::tr("Pareto front (points)"));
    rings->setMarkerShape(QScatterSeries::MarkerShapeCircle);
    rings->setMarkerSize(15);
    rings->setBrush(Qt::NoBrush);
    rings->setPen(QPen(frontColor, 1.6));
    for (const QPointF &p : front)
        rings->append(p.x(), axes.scale.map(p.y()));
    axes.attach(rings);
    axes.hideFromLegend(rings);
    for (const QPointF &value : rings->points())
        placer.markers.emplace_back(value, rings);
}

} // namespace

QChart *buildChart(const ChartSpec &spec)
{
    std::vector<double> xs, ys;
    for (const LabelledSeries &s : spec.series)
        for (const LabelledPoint &p : s.points)
            if (std::isfinite(p.x) && std::isfinite(p.y)) {
                xs.push_back(p.x);
                ys.push_back(p.y);
            }
    ChartAxes axes;
    axes.chart = styledChart(spec.title);
    axes.scale = chooseYScale(ys);
    axes.x = xAxisFor(xs, spec.xTitle);
    axes.chart->addAxis(axes.x, Qt::AlignBottom);
    axes.y = yAxisFor(axes.scale, spec);
    axes.chart->addAxis(axes.y, Qt::AlignLeft);

    auto placer = std::make_shared<LabelPlacer>();
    placer->chart = axes.chart;
    for (const LabelledSeries &s : spec.series)
        addSeries(axes, s, *placer);
    if (!spec.front.empty())
        addFront(axes, spec.front, *placer);
    // Keep the labels beside their points through resizes and zooms.
    keepLabelsPlaced(placer, axes.x, axes.y);
    return axes.chart;
}

QChart *createLabelledChart(const std::vector<LabelledSeries> &series, const QString &title,
                            const QString &xTitle, const QString &yTitle)
{
    ChartSpec spec;
    spec.title = title;
    spec.xTitle = xTitle;
    spec.yTitle = yTitle;
    spec.series = series;
    return buildChart(spec);
}

} // namespace phonglab
