#include "BenchTable.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace phonglab {

namespace {

QString number(double value, int precision, int width)
{
    if (std::isnan(value))
        return QStringLiteral("-").rightJustified(width);
    if (std::isinf(value))
        return QStringLiteral("inf").rightJustified(width);
    return QString::number(value, 'f', precision).rightJustified(width);
}

// "whole scene", or the object drawn alone ("1: cloud.obj"), cut to the column.
QString objectColumn(const BenchRow &row)
{
    if (row.isWholeScene())
        return QStringLiteral("whole scene");
    return row.object.size() <= 14 ? row.object : row.object.left(13) + QStringLiteral("…");
}

} // namespace

QString benchTableHeader()
{
    return QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9 %10 %11 %12 %13 %14")
        .arg(QStringLiteral("scene"), -10)
        .arg(QStringLiteral("object"), -14)
        .arg(QStringLiteral("method"), -11)
        .arg(QStringLiteral("detail"), 7)
        .arg(QStringLiteral("triangles"), 9)
        .arg(QStringLiteral("lights"), 6)
        .arg(QStringLiteral("frame ms"), 8)
        .arg(QStringLiteral("cpu ms"), 7)
        .arg(QStringLiteral("PSNR dB"), 7)
        .arg(QStringLiteral("RMSE"), 6)
        .arg(QStringLiteral("max"), 4)
        .arg(QStringLiteral("hl RMSE"), 7)
        .arg(QStringLiteral("hl max"), 6)
        .arg(QStringLiteral("cov px"), 6);
}

QString benchTableLine(const BenchRow &row)
{
    return QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9 %10 %11 %12 %13 %14")
        .arg(row.scene.left(10), -10)
        .arg(objectColumn(row), -14)
        .arg(row.method, -11)
        .arg(detailPercent(row.detail), 7)
        .arg(row.triangles, 9)
        .arg(QString::number(row.lights)
                 + (row.sceneLights ? QStringLiteral("*") : QStringLiteral(" ")),
             6)
        .arg(number(row.frameMs, 2, 8))
        .arg(number(row.cpuSubmitMs, 2, 7))
        .arg(number(row.psnr, 1, 7))
        .arg(number(row.rmse, 2, 6))
        .arg(row.maxError, 4)
        .arg(row.specularPixels ? number(row.specularRmse, 2, 7)
                                : QStringLiteral("-").rightJustified(7))
        .arg(row.specularPixels ? QString::number(row.specularMaxError).rightJustified(6)
                                : QStringLiteral("-").rightJustified(6))
        .arg(row.coverageErrors, 6);
}

std::vector<SceneFit> fitScenes(const std::vector<BenchRow> &rows, const ErrorBudget &budget)
{
    std::vector<SceneFit> fits;
    for (const BenchRow &row : rows) {
        if (!row.sceneLights || !row.isWholeScene())
            continue;
        auto it = std::find_if(fits.begin(), fits.end(),
                               [&](const SceneFit &f) { return f.scene == row.scene; });
        if (it == fits.end()) {
            fits.push_back(SceneFit{row.scene, {}, {}});
            it = std::prev(fits.end());
        }
        it->rows.push_back(row);
    }
    for (SceneFit &f : fits)
        f.fit = fitToBudget(f.rows, budget);
    return fits;
}

std::vector<SceneObjectFit> fitObjectsByScene(const std::vector<BenchRow> &rows,
                                              const ErrorBudget &budget)
{
    std::vector<QString> scenes; // in order of first appearance
    for (const BenchRow &row : rows)
        if (row.sceneLights && !row.isWholeScene()
            && std::find(scenes.begin(), scenes.end(), row.scene) == scenes.end())
            scenes.push_back(row.scene);
    std::vector<SceneObjectFit> fits;
    for (const QString &scene : scenes) {
        std::vector<BenchRow> own;
        std::copy_if(rows.begin(), rows.end(), std::back_inserter(own),
                     [&](const BenchRow &r) { return r.sceneLights && r.scene == scene; });
        fits.push_back({scene, fitObjects(own, budget)});
    }
    return fits;
}

QString sceneFitsToCsv(const std::vector<SceneFit> &fits, const ErrorBudget &budget)
{
    QString out = QStringLiteral("scene,budget,method,detail,triangles,frame_ms,max_error,psnr_db,"
                                 "baseline_triangles,baseline_frame_ms,triangles_saved,ms_saved\n");
    for (const SceneFit &f : fits) {
        const bool chosen = f.fit.chosen >= 0;
        const bool base = f.fit.baseline >= 0;
        const BenchRow none;
        const BenchRow &c = chosen ? f.rows[std::size_t(f.fit.chosen)] : none;
        const BenchRow &b = base ? f.rows[std::size_t(f.fit.baseline)] : none;
        out += QStringList{csvField(f.scene),
                           csvField(budget.describe()),
                           chosen ? c.method : QString(),
                           chosen ? QString::number(c.detail, 'g', 17) : QString(),
                           chosen ? QString::number(c.triangles) : QString(),
                           chosen ? QString::number(c.frameMs, 'g', 17) : QString(),
                           chosen ? QString::number(c.maxError) : QString(),
                           chosen ? (std::isinf(c.psnr) ? QStringLiteral("inf")
                                                        : QString::number(c.psnr, 'g', 17))
                                  : QString(),
                           base ? QString::number(b.triangles) : QString(),
                           base ? QString::number(b.frameMs, 'g', 17) : QString(),
                           chosen && base ? QString::number(f.fit.trianglesSaved) : QString(),
                           chosen && base ? QString::number(f.fit.msSaved, 'g', 17) : QString()}
                   .join(QLatin1Char(','))
            + QLatin1Char('\n');
    }
    return out;
}

} // namespace phonglab
