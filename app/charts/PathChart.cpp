#include "PathChart.h"

#include "ChartImages.h"
#include "core/support/Language.h"

#include <QCoreApplication>
#include <QGraphicsScene>
#include <QPen>
#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>

#include <algorithm>
#include <cmath>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct PathChartWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PathChart)
};

namespace {

QLineSeries *line(const QString &name, const QColor &color, Qt::PenStyle style = Qt::SolidLine)
{
    auto *series = new QLineSeries;
    series->setName(name);
    QPen pen(color);
    pen.setWidthF(2.0);
    pen.setStyle(style);
    series->setPen(pen);
    return series;
}

// Frames 0..last (the last frame's index), whole frames at about a dozen ticks.
QValueAxis *frameAxis(double last)
{
    auto *x = new QValueAxis;
    x->setTitleText(PathChartWords::tr("frame along the path"));
    x->setRange(0.0, std::max(1.0, last));
    x->setTickType(QValueAxis::TicksDynamic);
    x->setTickAnchor(0.0);
    x->setTickInterval(std::max(1.0, std::ceil(last / 12.0)));
    x->setLabelFormat(QStringLiteral("%.0f")); // localized labels need a precision
    return x;
}

// An axis from 0 to just above `top` 8-bit steps.
void setErrorTicks(QValueAxis *errorAxis, double top)
{
    // Whole steps at whole ticks: "%d" on ticks between them would lie.
    const double step = std::max(1.0, std::ceil((top + 1.0) / 8.0));
    errorAxis->setRange(0.0, step * std::ceil((top + 1.0) / step));
    errorAxis->setTickType(QValueAxis::TicksDynamic);
    errorAxis->setTickAnchor(0.0);
    errorAxis->setTickInterval(step);
    errorAxis->setLabelFormat(QStringLiteral("%.0f")); // localized labels need a precision
}

QChart *createPathChart(const PathRun &run, const ErrorBudget &budget)
{
    auto *chart = new QChart;
    chart->setLocalizeNumbers(true); // axis labels write numbers as the sentences do
    chart->setLocale(sentenceLocale());
    chart->setTitle(PathChartWords::tr("%1 — %2: %3 of %4 frames over budget (%5)")
                        .arg(run.scene, run.path)
                        .arg(run.overBudget())
                        .arg(run.frames.size())
                        .arg(budget.describe()));
    chart->legend()->setAlignment(Qt::AlignBottom);

    QLineSeries *error = line(PathChartWords::tr("max error (auto detail, unseen lights left out)"),
                              QColor(0xc0, 0x39, 0x2b));
    QLineSeries *fast = line(PathChartWords::tr("frame ms, auto detail"), QColor(0x1f, 0x6f, 0xb4));
    QLineSeries *full =
        line(PathChartWords::tr("frame ms, full detail"), QColor(0x7f, 0x8c, 0x8d), Qt::DashLine);
    double top = 0.0, ms = 0.0;
    for (const PathFrame &f : run.frames) {
        error->append(f.index, f.maxError);
        fast->append(f.index, f.frameMs);
        full->append(f.index, f.fullFrameMs);
        top = std::max(top, double(f.maxError));
        ms = std::max({ms, f.frameMs, f.fullFrameMs});
    }
    const double last = run.frames.empty() ? 1.0 : double(run.frames.back().index);
    for (QLineSeries *s : {error, fast, full})
        chart->addSeries(s);

    QValueAxis *x = frameAxis(last);
    auto *errorAxis = new QValueAxis;
    errorAxis->setTitleText(PathChartWords::tr("max error, 8-bit steps"));
    auto *msAxis = new QValueAxis;
    msAxis->setTitleText(PathChartWords::tr("ms per frame"));
    msAxis->setRange(0.0, ms * 1.15 + 0.1);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(errorAxis, Qt::AlignLeft);
    chart->addAxis(msAxis, Qt::AlignRight);
    if (budget.kind == ErrorBudget::Kind::MaxError) {
        QLineSeries *limit = line(QStringLiteral("budget"), QColor(0xc0, 0x39, 0x2b), Qt::DotLine);
        limit->append(0.0, budget.maxError);
        limit->append(std::max(1.0, last), budget.maxError);
        chart->addSeries(limit);
        limit->attachAxis(x);
        limit->attachAxis(errorAxis);
        top = std::max(top, double(budget.maxError));
    }
    setErrorTicks(errorAxis, top);
    for (QLineSeries *s : {error, fast, full})
        s->attachAxis(x);
    error->attachAxis(errorAxis);
    fast->attachAxis(msAxis);
    full->attachAxis(msAxis);
    return chart;
}

} // namespace

Result<> writePathCharts(const std::vector<PathRun> &runs, const ErrorBudget &budget,
                         const QString &pngPath, const QString &svgPath, QSize panelSize)
{
    if (Result<> app = haveApplication(); !app)
        return app;
    if (runs.empty() || panelSize.isEmpty())
        return fail(PathChartWords::tr("no camera path to chart"));
    const QSize total(panelSize.width(), panelSize.height() * int(runs.size()));
    QGraphicsScene scene(QRectF(QPointF(0, 0), QSizeF(total)));
    std::vector<QChart *> charts;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        QChart *chart = createPathChart(runs[i], budget);
        scene.addItem(chart);
        chart->setGeometry(
            QRectF(QPointF(0, double(panelSize.height()) * double(i)), QSizeF(panelSize)));
        charts.push_back(chart);
    }
    settleLayouts(charts);
    return renderScene(scene, total, pngPath, svgPath,
                       PathChartWords::tr("PhongLab camera paths: error and time per frame"));
}

} // namespace phonglab
