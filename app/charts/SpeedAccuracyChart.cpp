#include "SpeedAccuracyChart.h"
#include "ChartImages.h"
#include "LabelledChart.h"
#include "bench/ParetoFront.h"

#include <QCoreApplication>
#include <QGraphicsScene>
#include <QtCharts/QChart>
#include <iterator>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

// The bench's own charts on top of the general builder (LabelledChart.h) and
// image writer (ChartImages.h): which rows become which series and panels.

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct SpeedAccuracyChartWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::SpeedAccuracyChart)
};

namespace {

// flat < gouraud < faceted < blinn-phong < phong < normals < anything else (by name).
int methodRank(const QString &method)
{
    static const char *const order[] = {"flat",        "gouraud", "faceted",
                                        "blinn-phong", "phong",   "normals"};
    const int known = int(std::size(order));
    for (int i = 0; i < known; ++i)
        if (method == QLatin1String(order[i]))
            return i;
    return known;
}

bool methodLess(const QString &a, const QString &b)
{
    const int ra = methodRank(a), rb = methodRank(b);
    return ra != rb ? ra < rb : a < b;
}

QString lightsText(int lights, bool sceneLights)
{
    QString text =
        lights == 1 ? QStringLiteral("1 light") : QStringLiteral("%1 lights").arg(lights);
    if (sceneLights)
        text += QStringLiteral(" (scene's own)");
    return text;
}

} // namespace

QColor methodColor(const QString &method)
{
    if (method == QLatin1String("flat"))
        return QColor(0xe6, 0x7e, 0x22);
    if (method == QLatin1String("faceted"))
        return QColor(0xc0, 0x9a, 0x1a);
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

QChart *createSpeedAccuracyChart(const std::vector<BenchRow> &rows, const QString &title)
{
    ChartSpec spec;
    spec.title = title;
    spec.xTitle = SpeedAccuracyChartWords::tr("frame time (ms, median)");
    spec.yTitle = SpeedAccuracyChartWords::tr("error: RMSE");
    spec.yUnit = SpeedAccuracyChartWords::tr("8-bit steps");

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
            series.points.push_back({row->frameMs, row->rmse, detailPercent(row->detail)});
        spec.series.push_back(std::move(series));
    }

    for (int i : paretoFront(measured))
        spec.front.emplace_back(measured[i].frameMs, measured[i].rmse);

    return buildChart(spec);
}

Result<> writeNormalStudySeriesChart(std::vector<LabelledSeries> series, const QString &pngPath,
                                     const QString &svgPath, QSize size)
{
    if (Result<> app = haveApplication(); !app)
        return app;
    if (series.empty())
        return fail(SpeedAccuracyChartWords::tr("no normal-study rows to chart"));
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
        series, SpeedAccuracyChartWords::tr("Normal methods: time against angular error"),
        SpeedAccuracyChartWords::tr("time (ms)"),
        SpeedAccuracyChartWords::tr("mean angular error (degrees)")));
    return writeChartImages(chart.get(), pngPath, svgPath, size);
}

Result<> writeSpeedAccuracyCharts(const std::vector<BenchRow> &allRows, const QString &pngPath,
                                  const QString &svgPath, QSize panelSize)
{
    // The chart is of whole scenes; one object's rows belong to its fit.
    std::vector<BenchRow> rows;
    std::copy_if(allRows.begin(), allRows.end(), std::back_inserter(rows),
                 [](const BenchRow &row) { return row.isWholeScene(); });
    if (Result<> app = haveApplication(); !app)
        return app;
    if (panelSize.isEmpty())
        return fail(SpeedAccuracyChartWords::tr("panel size %1×%2 is empty")
                        .arg(panelSize.width())
                        .arg(panelSize.height()));

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
    if (scenes.isEmpty())
        return fail(SpeedAccuracyChartWords::tr("no benchmark rows to chart"));
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
            const QString title = QStringLiteral("%1 — %2").arg(
                scenes[r], lightsText(own[std::size_t(c)].first, own[std::size_t(c)].second));
            QChart *chart = createSpeedAccuracyChart(panel, title);
            scene.addItem(chart); // the scene owns it from here
            chart->setGeometry(
                QRectF(QPointF(c * panelSize.width(), r * panelSize.height()), QSizeF(panelSize)));
            charts.push_back(chart);
        }
    }
    settleLayouts(charts);
    return renderScene(scene, total, pngPath, svgPath,
                       SpeedAccuracyChartWords::tr("PhongLab: frame time against error"));
}

} // namespace phonglab
