// Draws the scaling benches' figures as PNG charts for docs/performance.md:
// log-log axes, one line per path, each named with its fitted slope.
//
//   bench_charts OUT_DIR FILE.csv...
// Reads the CSVs bench_scaling, bench_import_scaling and bench_memory write
// with --csv (rows `chart,series,x,y`, `# ` lines saying where they were
// measured) and writes frame-vs-triangles.png, frame-vs-pixels.png,
// reference-vs-pixels-triangles.png, import-vs-size.png and
// memory-vs-triangles.png into OUT_DIR, each only when its figures are
// there. Draws without a display server (the headless platform).
#include "LogLogFit.h"
#include "charts/ChartImages.h"
#include "headless/HeadlessPlatform.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QGraphicsScene>
#include <QPen>
#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QLogValueAxis>

#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

using namespace phonglab;

namespace {

struct Points {
    std::vector<double> x, y;
};

// Every chart's series, in the order the CSVs name them, and the notes of
// the file each chart came from.
struct Figures {
    std::map<QString, std::vector<std::pair<QString, Points>>> charts;
    std::map<QString, QStringList> notes;
};

bool readCsv(const QString &path, Figures &figures)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        std::fprintf(stderr, "cannot read %s: %s\n", qPrintable(path),
                     qPrintable(file.errorString()));
        return false;
    }
    QStringList notes;
    std::vector<QString> chartsHere;
    while (!file.atEnd()) {
        const QString line = QString::fromUtf8(file.readLine()).trimmed();
        if (line.startsWith(QLatin1String("# "))) {
            notes << line.mid(2);
            continue;
        }
        const QStringList cells = line.split(QLatin1Char(','));
        bool xOk = false, yOk = false;
        const double x = cells.value(2).toDouble(&xOk), y = cells.value(3).toDouble(&yOk);
        if (cells.size() != 4 || !xOk || !yOk || x <= 0 || y <= 0)
            continue; // the header, or a point a log axis cannot show
        auto &series = figures.charts[cells[0]];
        auto it = std::find_if(series.begin(), series.end(),
                               [&](const auto &s) { return s.first == cells[1]; });
        if (it == series.end())
            it = series.insert(series.end(), {cells[1], Points()});
        it->second.x.push_back(x);
        it->second.y.push_back(y);
        chartsHere.push_back(cells[0]);
    }
    for (const QString &chart : chartsHere)
        figures.notes[chart] = notes;
    return true;
}

struct Panel {
    const char *chart; // the CSV's chart name
    const char *title;
    const char *xTitle;
    const char *yTitle;
    bool topSlope = true; // also the slope over the largest three points in the legend
};

struct Picture {
    const char *file;
    std::vector<Panel> panels; // side by side
};

const std::vector<Picture> &pictures()
{
    static const std::vector<Picture> all = {
        {"frame-vs-triangles.png",
         {{"frame-vs-triangles", "Frame time against triangles (UV sphere, 800×600)", "triangles",
           "ms per frame (render + glFinish)"}}},
        {"frame-vs-pixels.png",
         {{"frame-vs-pixels", "Frame time against pixels (200,704-triangle sphere)", "megapixels",
           "ms per frame (render + glFinish)"}}},
        {"reference-vs-pixels-triangles.png",
         {{"reference-vs-triangles", "Exact reference against triangles (800×600)", "triangles",
           "ms per image"},
          {"reference-vs-pixels", "Exact reference against pixels (200,704 triangles)",
           "megapixels", "ms per image"}}},
        {"import-vs-size.png",
         {{"import-vs-size", "Import time against file size (OBJ with normals, UV sphere)",
           "file size, MB", "ms to open"}}},
        {"memory-vs-triangles.png",
         {{"memory-vs-triangles", "Memory against triangles (UV sphere)", "triangles",
           "MB (10^6 bytes)", false}}},
    };
    return all;
}

QColor colorOf(std::size_t i)
{
    static const QColor colors[] = {QColor(0x1f, 0x6f, 0xb4), QColor(0xc0, 0x39, 0x2b),
                                    QColor(0x27, 0xae, 0x60), QColor(0x8e, 0x44, 0xad),
                                    QColor(0xd3, 0x84, 0x00), QColor(0x7f, 0x8c, 0x8d)};
    return colors[i % std::size(colors)];
}

// "name: slope 0.56 (largest three 0.76)", the fit over log-log points.
QString legendName(const QString &name, const Points &p, bool topSlope)
{
    if (p.x.size() < 2)
        return name;
    const double all = bench::logLogSlope(p.x, p.y);
    if (p.x.size() <= 3 || !topSlope)
        return QStringLiteral("%1: slope %2").arg(name).arg(all, 0, 'f', 2);
    return QStringLiteral("%1: slope %2 (largest three %3)")
        .arg(name)
        .arg(all, 0, 'f', 2)
        .arg(bench::logLogSlope(p.x, p.y, bench::largestThree(p.x)), 0, 'f', 2);
}

// A base-10 log axis over whole decades around [low, high].
QLogValueAxis *logAxis(const QString &title, double low, double high)
{
    auto *axis = new QLogValueAxis;
    axis->setBase(10.0);
    axis->setTitleText(title);
    // Whole numbers in full up to 10^7 (no "1e+06"), fractions as they come.
    axis->setLabelFormat(high >= 1e5 ? QStringLiteral("%.0f") : QStringLiteral("%g"));
    axis->setMinorTickCount(8);
    axis->setRange(std::pow(10.0, std::floor(std::log10(low))),
                   std::pow(10.0, std::ceil(std::log10(high))));
    return axis;
}

QChart *buildPanel(const Panel &panel, const std::vector<std::pair<QString, Points>> &series,
                   const QStringList &notes)
{
    auto *chart = new QChart;
    QString title = QStringLiteral("<b>%1</b>").arg(QString::fromUtf8(panel.title));
    for (const QString &note : notes)
        title += QStringLiteral("<br><small>%1</small>").arg(note.toHtmlEscaped());
    chart->setTitle(title);
    chart->legend()->setAlignment(Qt::AlignBottom);
    double xLow = INFINITY, xHigh = 0, yLow = INFINITY, yHigh = 0;
    std::vector<QLineSeries *> lines;
    for (std::size_t i = 0; i < series.size(); ++i) {
        const Points &p = series[i].second;
        auto *line = new QLineSeries;
        line->setName(legendName(series[i].first, p, panel.topSlope));
        QPen pen(colorOf(i));
        pen.setWidthF(2.0);
        line->setPen(pen);
        line->setPointsVisible(true);
        for (std::size_t k = 0; k < p.x.size(); ++k) {
            line->append(p.x[k], p.y[k]);
            xLow = std::min(xLow, p.x[k]);
            xHigh = std::max(xHigh, p.x[k]);
            yLow = std::min(yLow, p.y[k]);
            yHigh = std::max(yHigh, p.y[k]);
        }
        chart->addSeries(line);
        lines.push_back(line);
    }
    QLogValueAxis *x = logAxis(QString::fromUtf8(panel.xTitle), xLow, xHigh);
    QLogValueAxis *y = logAxis(QString::fromUtf8(panel.yTitle), yLow, yHigh);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QLineSeries *line : lines) {
        line->attachAxis(x);
        line->attachAxis(y);
    }
    return chart;
}

// False after saying why; true (and nothing written) when the picture's
// figures are not among the CSVs.
bool writePicture(const Picture &picture, const Figures &figures, const QDir &out)
{
    const QSize panelSize(900, 600);
    std::vector<const Panel *> present;
    for (const Panel &panel : picture.panels)
        if (figures.charts.count(QString::fromUtf8(panel.chart)))
            present.push_back(&panel);
    if (present.empty())
        return true;
    const QSize total(panelSize.width() * int(present.size()), panelSize.height());
    QGraphicsScene scene(QRectF(QPointF(0, 0), QSizeF(total)));
    std::vector<QChart *> charts;
    for (std::size_t i = 0; i < present.size(); ++i) {
        const QString name = QString::fromUtf8(present[i]->chart);
        QChart *chart = buildPanel(*present[i], figures.charts.at(name), figures.notes.at(name));
        scene.addItem(chart);
        chart->setGeometry(
            QRectF(QPointF(double(panelSize.width()) * double(i), 0.0), QSizeF(panelSize)));
        charts.push_back(chart);
    }
    settleLayouts(charts);
    const QString path = out.filePath(QString::fromUtf8(picture.file));
    if (const Result<> written = renderScene(scene, total, path, QString(), path); !written) {
        std::fprintf(stderr, "%s\n", qPrintable(written.error()));
        return false;
    }
    std::printf("wrote %s\n", qPrintable(path));
    return true;
}

} // namespace

int main(int argc, char **argv)
{
    chooseCommandPlatform();
    QApplication app(argc, argv);
    const QStringList args = app.arguments().mid(1);
    if (args.size() < 2) {
        std::fprintf(stderr, "usage: bench_charts OUT_DIR FILE.csv...\n");
        return 2;
    }
    Figures figures;
    for (const QString &csv : args.mid(1))
        if (!readCsv(csv, figures))
            return 1;
    QDir out(args.front());
    if (!out.mkpath(QStringLiteral("."))) {
        std::fprintf(stderr, "cannot make %s\n", qPrintable(out.path()));
        return 1;
    }
    for (const Picture &picture : pictures())
        if (!writePicture(picture, figures, out))
            return 1;
    return 0;
}
