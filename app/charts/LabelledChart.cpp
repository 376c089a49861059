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

} // namespace

QChart *buildChart(const ChartSpec &spec)
{
    auto *chart = new QChart;
    chart->setLocalizeNumbers(true); // axis labels write numbers as the sentences do
    chart->setLocale(sentenceLocale());
    chart->setTitle(spec.title);
    chart->setTitleFont(sizedFont(chart->titleFont(), 11, true));
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->setDropShadowEnabled(false);
    chart->setBackgroundRoundness(0);
    chart->setMargins(QMargins(6, 4, 10, 4));
    chart->legend()->setAlignment(Qt::AlignBottom);
    chart->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries);
    chart->legend()->setFont(sizedFont(chart->legend()->font(), 8.5));

    std::vector<double> xs, ys;
    for (const LabelledSeries &s : spec.series)
        for (const LabelledPoint &p : s.points)
            if (std::isfinite(p.x) && std::isfinite(p.y)) {
                xs.push_back(p.x);
                ys.push_back(p.y);
            }
    const YScale yScale = chooseYScale(ys);

    // Axes.
    auto *xAxis = new QValueAxis;
    xAxis->setTitleText(spec.xTitle);
    xAxis->setTitleFont(sizedFont(xAxis->titleFont(), 9));
    xAxis->setLabelsFont(sizedFont(xAxis->labelsFont(), 8));
    xAxis->setLabelFormat(QStringLiteral("%.6g")); // localized labels need a precision
    double xMin = 0, xMax = 1;
    if (!xs.empty()) {
        xMin = *std::min_element(xs.begin(), xs.end());
        xMax = *std::max_element(xs.begin(), xs.end());
        const double span = xMax - xMin;
        const double pad = span > 0 ? span * 0.1 : std::max(std::abs(xMax) * 0.1, 0.1);
        xMin = std::max(0.0, xMin - pad);
        xMax = xMax + pad * 1.5; // room on the right for labels
    }
    xAxis->setRange(xMin, xMax);
    xAxis->setTickCount(6);
    xAxis->applyNiceNumbers();
    chart->addAxis(xAxis, Qt::AlignBottom);

    QAbstractAxis *yAxis = nullptr;
    QStringList yNotes;
    if (!spec.yUnit.isEmpty())
        yNotes << spec.yUnit;
    if (yScale.log) {
        auto *axis = new QLogValueAxis;
        axis->setBase(10);
        axis->setLabelFormat(QStringLiteral("%.6g")); // localized labels need a precision
        axis->setMinorTickCount(8);
        axis->setMinorGridLineColor(QColor(238, 238, 238));
        axis->setRange(yScale.min, yScale.max);
        yNotes
            << (yScale.hasZero
                    ? LabelledChartWords::tr("log; 0 drawn at %1").arg(trimmedNumber(yScale.floor))
                    : QStringLiteral("log"));
        yAxis = axis;
    } else {
        auto *axis = new QValueAxis;
        axis->setLabelFormat(QStringLiteral("%.6g")); // localized labels need a precision
        axis->setRange(yScale.min, yScale.max);
        axis->setTickCount(6);
        axis->applyNiceNumbers();
        yAxis = axis;
    }
    yAxis->setTitleText(yNotes.isEmpty() ? spec.yTitle
                                         : QStringLiteral("%1 (%2)").arg(
                                             spec.yTitle, yNotes.join(QStringLiteral(", "))));
    yAxis->setTitleFont(sizedFont(yAxis->titleFont(), 9));
    yAxis->setLabelsFont(sizedFont(yAxis->labelsFont(), 8));
    chart->addAxis(yAxis, Qt::AlignLeft);

    auto attach = [&](QAbstractSeries *series) {
        chart->addSeries(series);
        series->attachAxis(xAxis);
        series->attachAxis(yAxis);
    };
    auto hideLegend = [&](QAbstractSeries *series) {
        for (QLegendMarker *marker : chart->legend()->markers(series))
            marker->setVisible(false);
    };

    const QColor frontColor(110, 110, 110);

    auto placer = std::make_shared<LabelPlacer>();
    placer->chart = chart;
    const QFont labelFont = sizedFont(chart->titleFont(), 7.5, false);

    for (const LabelledSeries &s : spec.series) {
        auto *line = new QLineSeries;
        line->setName(s.name);
        line->setPen(QPen(s.color, 1.8));
        auto *markers = new QScatterSeries;
        markers->setName(s.name);
        markers->setMarkerShape(QScatterSeries::MarkerShapeCircle);
        markers->setMarkerSize(8);
        markers->setColor(s.color);
        markers->setBorderColor(s.color.darker(140));
        for (const LabelledPoint &p : s.points) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y))
                continue;
            const QPointF value(p.x, yScale.map(p.y));
            line->append(value);
            markers->append(value);
        }
        attach(line);
        attach(markers);
        hideLegend(line);
        placer->lines.push_back(line);
        for (const QPointF &value : markers->points())
            placer->markers.emplace_back(value, markers);
        int index = 0;
        for (const LabelledPoint &p : s.points) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y))
                continue;
            const QPointF value = markers->at(index++);
            if (p.label.isEmpty())
                continue;
            auto *item = new QGraphicsSimpleTextItem(p.label, chart);
            item->setFont(labelFont);
            item->setBrush(s.color.darker(150));
            item->setZValue(1000);
            placer->labels.push_back({item, value, markers});
        }
    }

    // The front after the methods, so the legend lists it last: a dashed
    // step line (everything above and right of it is beaten) and rings.
    if (!spec.front.empty()) {
        auto *step = new QLineSeries;
        step->setName(LabelledChartWords::tr("Pareto front"));
        step->setPen(QPen(frontColor, 1.4, Qt::DashLine));
        for (size_t i = 0; i < spec.front.size(); ++i) {
            const QPointF p(spec.front[i].x(), yScale.map(spec.front[i].y()));
            if (i > 0)
                step->append(p.x(), yScale.map(spec.front[i - 1].y()));
            step->append(p);
        }
        attach(step);
        placer->lines.push_back(step);

        auto *rings = new QScatterSeries;
        rings->setName(LabelledChartWords::tr("Pareto front (points)"));
        rings->setMarkerShape(QScatterSeries::MarkerShapeCircle);
        rings->setMarkerSize(15);
        rings->setBrush(Qt::NoBrush);
        rings->setPen(QPen(frontColor, 1.6));
        for (const QPointF &p : spec.front)
            rings->append(p.x(), yScale.map(p.y()));
        attach(rings);
        hideLegend(rings);
        for (const QPointF &value : rings->points())
            placer->markers.emplace_back(value, rings);
    }

    // Keep the labels beside their points through resizes and zooms.
    keepLabelsPlaced(placer, xAxis, yAxis);
    return chart;
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
