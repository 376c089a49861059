#pragma once
#include "bench/ErrorBudget.h"
#include "bench/PathBench.h"
#include "core/support/Result.h"

#include <QSize>
#include <QString>
#include <vector>

namespace phonglab {

// `phonglab bench --path`'s picture: one panel per run (scene and path),
// stacked, each with the frames along the path on x, the frame's max error
// (8-bit steps, left axis) against the budget's line, and the frame time
// with auto detail against full detail (ms, right axis). Written as PNG and
// SVG like writeChartImages(). A failure without a QApplication or runs.
Result<> writePathCharts(const std::vector<PathRun> &runs, const ErrorBudget &budget,
                         const QString &pngPath, const QString &svgPath,
                         QSize panelSize = QSize(900, 360));

} // namespace phonglab
