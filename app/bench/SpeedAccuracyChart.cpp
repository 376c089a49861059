#include "SpeedAccuracyChart.h"
#include "ParetoFront.h"

#include <QApplication>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QImage>
#include <QImageWriter>
#include <QPainter>
#include <QSaveFile>
#include <QSvgGenerator>
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
#include <map>
#include <memory>

namespace phonglab {

namespace {

QString formatPercent(double fraction)
{
    const double percent = fraction * 100.0;
    if (std::abs(percent) >= 100)
        return QString::number(percent, 'f', 0) + QStringLiteral(" %");
    return QString::number(percent, 'g', 3) + QStringLiteral(" %");
}

// flat < gouraud < blinn-phong < phong < normals < anything else (by name).
int methodRank(const QString &method)
{
    static const char *const order[] = {"flat", "gouraud", "blinn-phong", "phong", "normals"};
    for (int i = 0; i < 5; ++i)
        if (method == QLatin1String(order[i]))
            return i;
    return 5;
}

bool methodLess(const QString &a, const QString &b)
{
    const int ra = methodRank(a), rb = methodRank(b);
    return ra != rb ? ra < rb : a < b;
}

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
    return QString::number(v, 'g', 6);
}

// Point labels: plain text items on the chart, placed after every layout
// (resize, zoom) next to their point where they hit no other label and no
// marker.
struct PointLabel {
    QGraphicsSimpleTextItem *item = nullptr;
    QPointF value;
    QAbstractSeries *series = nullptr;
};

struct LabelPlacer {
    QChart *chart = nullptr;
    std::vector<PointLabel> labels;
    std::vector<std::pair<QPointF, QAbstractSeries *>> markers; // obstacles
    std::vector<QXYSeries *> lines; // lines are lighter obstacles than markers and labels

    void place() const
    {
        const QRectF plot = chart->plotArea();
        if (plot.isEmpty())
            return;
        const QRectF inside = plot.adjusted(-0.5, -0.5, 0.5, 0.5);
        std::vector<QRectF> taken;
        for (const auto &[value, series] : markers) {
            const QPointF p = chart->mapToPosition(value, series);
            taken.emplace_back(p.x() - 5, p.y() - 5, 10, 10);
        }
        auto overlap = [](const QRectF &a, const QRectF &b) {
            const QRectF i = a.intersected(b);
            return i.isEmpty() ? 0.0 : i.width() * i.height();
        };
        // Lines as small squares every few pixels along them.
        std::vector<QRectF> lineDots;
        for (QXYSeries *line : lines) {
            const QList<QPointF> points = line->points();
            for (qsizetype i = 1; i < points.size(); ++i) {
                const QPointF a = chart->mapToPosition(points[i - 1], line);
                const QPointF b = chart->mapToPosition(points[i], line);
                const double length = QLineF(a, b).length();
                const int steps = std::clamp(int(length / 4.0), 1, 2000);
                for (int k = 0; k <= steps; ++k) {
                    const QPointF p = a + (b - a) * (double(k) / steps);
                    lineDots.emplace_back(p.x() - 1.5, p.y() - 1.5, 3, 3);
                }
            }
        }
        for (const PointLabel &label : labels) {
            const QPointF p = chart->mapToPosition(label.value, label.series);
            if (!inside.contains(p)) {
                label.item->setVisible(false);
                continue;
            }
            label.item->setVisible(true);
            const QSizeF s = label.item->boundingRect().size();
            const double w = s.width(), h = s.height();
            const QPointF offsets[] = {
                {7, -h / 2},          // right
                {5, -h - 1},          // above right
                {-w / 2, -h - 6},     // above
                {5, 1},               // below right
                {-w / 2, 6},          // below
                {-7 - w, -h / 2},     // left
                {-5 - w, -h - 1},     // above left
                {-5 - w, 1},          // below left
                {12, -h / 2},         // further right
                {-w / 2, -h - 14},    // further above
                {-w / 2, 14},         // further below
                {-12 - w, -h / 2},    // further left
            };
            QRectF best;
            double bestScore = std::numeric_limits<double>::infinity();
            for (const QPointF &offset : offsets) {
                const QRectF r(p + offset, s);
                double score = 0;
                for (const QRectF &t : taken)
                    score += overlap(r, t);
                for (const QRectF &t : lineDots)
                    score += 0.5 * overlap(r, t);
                const double outside = w * h - overlap(r, plot);
                score += outside * 2.0;
                if (score < bestScore - 1e-9) {
                    bestScore = score;
                    best = r;
                    if (score <= 0)
                        break;
                }
            }
            label.item->setPos(best.topLeft());
            taken.push_back(best);
        }
    }
};

struct ChartSpec {
    QString title;
    QString xTitle;
    QString yTitle; // e.g. "error: RMSE against the reference"
    QString yUnit;  // e.g. "8-bit steps"; the scale note joins it in parentheses
    std::vector<LabelledSeries> series;
    std::vector<QPointF> front; // raw (x, y), sorted by x; empty: no front
};

QFont sizedFont(QFont font, double pointSize, bool bold = false)
{
    font.setPointSizeF(pointSize);
    font.setBold(bold);
    return font;
}

QChart *buildChart(const ChartSpec &spec)
{
    auto *chart = new QChart;
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
    xAxis->setLabelFormat(QStringLiteral("%g"));
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
        axis->setLabelFormat(QStringLiteral("%g"));
        axis->setMinorTickCount(8);
        axis->setMinorGridLineColor(QColor(238, 238, 238));
        axis->setRange(yScale.min, yScale.max);
        yNotes << (yScale.hasZero
                       ? QStringLiteral("log; 0 drawn at %1").arg(trimmedNumber(yScale.floor))
                       : QStringLiteral("log"));
        yAxis = axis;
    } else {
        auto *axis = new QValueAxis;
        axis->setLabelFormat(QStringLiteral("%g"));
        axis->setRange(yScale.min, yScale.max);
        axis->setTickCount(6);
        axis->applyNiceNumbers();
        yAxis = axis;
    }
    yAxis->setTitleText(yNotes.isEmpty() ? spec.yTitle
                                         : QStringLiteral("%1 (%2)").arg(spec.yTitle, yNotes.join(QStringLiteral(", "))));
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
        step->setName(QStringLiteral("Pareto front"));
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
        rings->setName(QStringLiteral("Pareto front (points)"));
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
    QObject::connect(chart, &QChart::plotAreaChanged, chart, [placer] { placer->place(); });
    QObject::connect(xAxis, &QValueAxis::rangeChanged, chart, [placer] { placer->place(); });
    if (auto *axis = qobject_cast<QValueAxis *>(yAxis))
        QObject::connect(axis, &QValueAxis::rangeChanged, chart, [placer] { placer->place(); });
    if (auto *axis = qobject_cast<QLogValueAxis *>(yAxis))
        QObject::connect(axis, &QLogValueAxis::rangeChanged, chart, [placer] { placer->place(); });
    placer->place();
    return chart;
}

bool haveApplication(QString *error)
{
    if (qobject_cast<QApplication *>(QCoreApplication::instance()))
        return true;
    if (error)
        *error = QStringLiteral("charts need a QApplication (Qt Charts are widgets)");
    return false;
}

// Lays out every chart in the scene (layouts are otherwise deferred to the
// event loop) so the point labels sit where they will be drawn.
void settleLayouts(const std::vector<QChart *> &charts)
{
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    for (QChart *chart : charts)
        if (chart->layout())
            chart->layout()->activate();
}

// Renders `scene` (size × size) to PNG and SVG through QSaveFile.
bool renderScene(QGraphicsScene &scene, const QSize &size, const QString &pngPath,
                 const QString &svgPath, const QString &title, QString *error)
{
    auto fail = [&](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    if (pngPath.isEmpty() && svgPath.isEmpty())
        return fail(QStringLiteral("no output file given"));

    const QRectF rect(QPointF(0, 0), QSizeF(size));

    // Open both first so a bad path writes nothing.
    QSaveFile pngFile(pngPath), svgFile(svgPath);
    if (!pngPath.isEmpty() && !pngFile.open(QIODevice::WriteOnly))
        return fail(QStringLiteral("cannot write %1: %2").arg(pngPath, pngFile.errorString()));
    if (!svgPath.isEmpty() && !svgFile.open(QIODevice::WriteOnly))
        return fail(QStringLiteral("cannot write %1: %2").arg(svgPath, svgFile.errorString()));

    if (!pngPath.isEmpty()) {
        QImage image(size, QImage::Format_ARGB32_Premultiplied);
        image.setDevicePixelRatio(1.0);
        image.fill(Qt::white);
        {
            QPainter painter(&image);
            painter.setRenderHint(QPainter::Antialiasing);
            painter.setRenderHint(QPainter::TextAntialiasing);
            scene.render(&painter, rect, rect);
        }
        QImageWriter writer(&pngFile, "png");
        if (!writer.write(image))
            return fail(QStringLiteral("cannot write %1: %2").arg(pngPath, writer.errorString()));
    }
    if (!svgPath.isEmpty()) {
        QSvgGenerator generator;
        generator.setOutputDevice(&svgFile);
        generator.setSize(size);
        generator.setViewBox(rect);
        generator.setResolution(96);
        generator.setTitle(title);
        generator.setDescription(QStringLiteral("PhongLab benchmark chart"));
        QPainter painter;
        if (!painter.begin(&generator))
            return fail(QStringLiteral("cannot write %1: SVG output failed").arg(svgPath));
        painter.setRenderHint(QPainter::Antialiasing);
        painter.fillRect(rect, Qt::white);
        scene.render(&painter, rect, rect);
        painter.end();
    }
    if (!pngPath.isEmpty() && !pngFile.commit())
        return fail(QStringLiteral("cannot write %1: %2").arg(pngPath, pngFile.errorString()));
    if (!svgPath.isEmpty() && !svgFile.commit())
        return fail(QStringLiteral("cannot write %1: %2").arg(svgPath, svgFile.errorString()));
    return true;
}

QString lightsText(int lights, bool sceneLights)
{
    QString text = lights == 1 ? QStringLiteral("1 light") : QStringLiteral("%1 lights").arg(lights);
    if (sceneLights)
        text += QStringLiteral(" (scene's own)");
    return text;
}

} // namespace

QColor methodColor(const QString &method)
{
    if (method == QLatin1String("flat"))
        return QColor(0xe6, 0x7e, 0x22);
    if (method == QLatin1String("gouraud"))
        return QColor(0x2c, 0xa0, 0x2c);
    if (method == QLatin1String("blinn-phong"))
        return QColor(0x8e, 0x44, 0xad);
    if (method == QLatin1String("phong"))
        return QColor(0x1f, 0x6f, 0xb4);
    if (method == QLatin1String("normals"))
        return QColor(0x8c, 0x56, 0x4b);
    // Anything else: a stable hue from the name (not qHash, which is seeded).
    quint32 h = 2166136261u;
    for (QChar c : method)
        h = (h ^ c.unicode()) * 16777619u;
    return QColor::fromHsv(int(h % 360), 170, 190);
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

QChart *createSpeedAccuracyChart(const std::vector<BenchRow> &rows, const QString &title)
{
    ChartSpec spec;
    spec.title = title;
    spec.xTitle = QStringLiteral("frame time (ms, median)");
    spec.yTitle = QStringLiteral("error: RMSE");
    spec.yUnit = QStringLiteral("8-bit steps");

    std::map<QString, std::vector<const BenchRow *>, decltype(&methodLess)> byMethod(&methodLess);
    std::vector<BenchRow> measured;
    for (const BenchRow &row : rows) {
        if (std::isnan(row.frameMs) || std::isnan(row.rmse))
            continue;
        measured.push_back(row);
    }
    for (const BenchRow &row : measured)
        byMethod[row.method].push_back(&row);

    for (auto &[method, list] : byMethod) {
        std::stable_sort(list.begin(), list.end(), [](const BenchRow *a, const BenchRow *b) {
            return a->detail < b->detail;
        });
        LabelledSeries series;
        series.name = method;
        series.color = methodColor(method);
        for (const BenchRow *row : list)
            series.points.push_back({row->frameMs, row->rmse, formatPercent(row->detail)});
        spec.series.push_back(std::move(series));
    }

    for (int i : paretoFront(measured))
        spec.front.emplace_back(measured[i].frameMs, measured[i].rmse);

    return buildChart(spec);
}

bool writeChartImages(QChart *chart, const QString &pngPath, const QString &svgPath,
                      QString *error, QSize size)
{
    if (!haveApplication(error))
        return false;
    if (!chart || size.isEmpty()) {
        if (error)
            *error = QStringLiteral("nothing to draw");
        return false;
    }
    QGraphicsScene scene(QRectF(QPointF(0, 0), QSizeF(size)));
    scene.addItem(chart);
    chart->setGeometry(QRectF(QPointF(0, 0), QSizeF(size)));
    settleLayouts({chart});
    const bool ok = renderScene(scene, size, pngPath, svgPath, chart->title(), error);
    scene.removeItem(chart); // the chart stays the caller's
    return ok;
}

bool writeNormalStudySeriesChart(std::vector<LabelledSeries> series, const QString &pngPath,
                                 const QString &svgPath, QString *error, QSize size)
{
    if (!haveApplication(error))
        return false;
    if (series.empty()) {
        if (error)
            *error = QStringLiteral("no normal-study rows to chart");
        return false;
    }
    // Tessellations have no fixed colours of their own: a fixed sequence.
    static const QColor palette[] = {QColor(0x1f, 0x6f, 0xb4), QColor(0xe6, 0x7e, 0x22),
                                     QColor(0x2c, 0xa0, 0x2c), QColor(0xc0, 0x39, 0x2b),
                                     QColor(0x8e, 0x44, 0xad), QColor(0x8c, 0x56, 0x4b),
                                     QColor(0x17, 0xa2, 0xb8), QColor(0x7f, 0x7f, 0x7f)};
    for (size_t i = 0; i < series.size(); ++i) {
        if (!series[i].color.isValid())
            series[i].color = palette[i % std::size(palette)];
        std::stable_sort(series[i].points.begin(), series[i].points.end(),
                         [](const LabelledPoint &a, const LabelledPoint &b) { return a.x < b.x; });
    }
    std::unique_ptr<QChart> chart(createLabelledChart(
        series, QStringLiteral("Normal methods: time against angular error"),
        QStringLiteral("time (ms)"), QStringLiteral("mean angular error (degrees)")));
    return writeChartImages(chart.get(), pngPath, svgPath, error, size);
}

bool writeSpeedAccuracyCharts(const std::vector<BenchRow> &rows, const QString &pngPath,
                              const QString &svgPath, QString *error, QSize panelSize)
{
    if (!haveApplication(error))
        return false;
    if (panelSize.isEmpty()) {
        if (error)
            *error = QStringLiteral("panel size %1×%2 is empty").arg(panelSize.width()).arg(panelSize.height());
        return false;
    }

    // Grid rows: scenes in order of first appearance; along each row that
    // scene's light setups by count (its own lights among them), packed
    // left so scenes with different setups leave no holes.
    QStringList scenes;
    std::vector<std::vector<std::pair<int, bool>>> setups; // per scene
    for (const BenchRow &row : rows) {
        if (!scenes.contains(row.scene)) {
            scenes.append(row.scene);
            setups.emplace_back();
        }
        auto &own = setups[std::size_t(scenes.indexOf(row.scene))];
        const std::pair<int, bool> setup(row.lights, row.sceneLights);
        if (std::find(own.begin(), own.end(), setup) == own.end())
            own.push_back(setup);
    }
    if (scenes.isEmpty()) {
        if (error)
            *error = QStringLiteral("no benchmark rows to chart");
        return false;
    }
    std::size_t columns = 0;
    for (auto &own : setups) {
        std::sort(own.begin(), own.end());
        columns = std::max(columns, own.size());
    }

    const QSize total(panelSize.width() * int(columns), panelSize.height() * int(scenes.size()));
    QGraphicsScene scene(QRectF(QPointF(0, 0), QSizeF(total)));
    std::vector<QChart *> charts;
    for (int r = 0; r < scenes.size(); ++r) {
        const auto &own = setups[std::size_t(r)];
        for (int c = 0; c < int(own.size()); ++c) {
            std::vector<BenchRow> panel;
            for (const BenchRow &row : rows)
                if (row.scene == scenes[r] && row.lights == own[std::size_t(c)].first
                    && row.sceneLights == own[std::size_t(c)].second)
                    panel.push_back(row);
            const QString title = QStringLiteral("%1 — %2")
                                      .arg(scenes[r], lightsText(own[std::size_t(c)].first, own[std::size_t(c)].second));
            QChart *chart = createSpeedAccuracyChart(panel, title);
            scene.addItem(chart); // the scene owns it from here
            chart->setGeometry(QRectF(QPointF(c * panelSize.width(), r * panelSize.height()),
                                      QSizeF(panelSize)));
            charts.push_back(chart);
        }
    }
    settleLayouts(charts);
    return renderScene(scene, total, pngPath, svgPath,
                       QStringLiteral("PhongLab: frame time against error"), error);
}

} // namespace phonglab
