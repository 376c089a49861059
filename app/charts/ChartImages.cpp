#include "ChartImages.h"
#include "SpeedAccuracyChart.h"

#include <QApplication>
#include <QCoreApplication>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QImage>
#include <QImageWriter>
#include <QPainter>
#include <QSaveFile>
#include <QSvgGenerator>
#include <QtCharts/QChart>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ChartImagesWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ChartImages)
};

Result<> haveApplication()
{
    if (qobject_cast<QApplication *>(QCoreApplication::instance()))
        return {};
    return fail(ChartImagesWords::tr("charts need a QApplication (Qt Charts are widgets)"));
}

void settleLayouts(const std::vector<QChart *> &charts)
{
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    for (QChart *chart : charts)
        if (chart->layout())
            chart->layout()->activate();
}

Result<> renderScene(QGraphicsScene &scene, const QSize &size, const QString &pngPath,
                     const QString &svgPath, const QString &title)
{
    if (pngPath.isEmpty() && svgPath.isEmpty())
        return fail(ChartImagesWords::tr("no output file given"));

    const QRectF rect(QPointF(0, 0), QSizeF(size));

    // Open both first so a bad path writes nothing.
    QSaveFile pngFile(pngPath), svgFile(svgPath);
    if (!pngPath.isEmpty() && !pngFile.open(QIODevice::WriteOnly))
        return fail(
            ChartImagesWords::tr("cannot write %1: %2").arg(pngPath, pngFile.errorString()));
    if (!svgPath.isEmpty() && !svgFile.open(QIODevice::WriteOnly))
        return fail(
            ChartImagesWords::tr("cannot write %1: %2").arg(svgPath, svgFile.errorString()));

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
            return fail(
                ChartImagesWords::tr("cannot write %1: %2").arg(pngPath, writer.errorString()));
    }
    if (!svgPath.isEmpty()) {
        QSvgGenerator generator;
        generator.setOutputDevice(&svgFile);
        generator.setSize(size);
        generator.setViewBox(rect);
        generator.setResolution(96);
        generator.setTitle(title);
        generator.setDescription(ChartImagesWords::tr("PhongLab benchmark chart"));
        QPainter painter;
        if (!painter.begin(&generator))
            return fail(ChartImagesWords::tr("cannot write %1: SVG output failed").arg(svgPath));
        painter.setRenderHint(QPainter::Antialiasing);
        painter.fillRect(rect, Qt::white);
        scene.render(&painter, rect, rect);
        painter.end();
    }
    if (!pngPath.isEmpty() && !pngFile.commit())
        return fail(
            ChartImagesWords::tr("cannot write %1: %2").arg(pngPath, pngFile.errorString()));
    if (!svgPath.isEmpty() && !svgFile.commit())
        return fail(
            ChartImagesWords::tr("cannot write %1: %2").arg(svgPath, svgFile.errorString()));
    return {};
}

Result<> writeChartImages(QChart *chart, const QString &pngPath, const QString &svgPath, QSize size)
{
    if (Result<> app = haveApplication(); !app)
        return app;
    if (!chart || size.isEmpty())
        return fail(ChartImagesWords::tr("nothing to draw"));
    QGraphicsScene scene(QRectF(QPointF(0, 0), QSizeF(size)));
    scene.addItem(chart);
    chart->setGeometry(QRectF(QPointF(0, 0), QSizeF(size)));
    settleLayouts({chart});
    Result<> rendered = renderScene(scene, size, pngPath, svgPath, chart->title());
    scene.removeItem(chart); // the chart stays the caller's
    return rendered;
}

} // namespace phonglab
