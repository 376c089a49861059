#pragma once
#include "BenchResult.h"
#include "ErrorBudget.h"
#include "ObjectFit.h"

#include <QString>
#include <vector>

namespace phonglab {

// The terminal table `phonglab bench` prints, one line per row.
QString benchTableHeader();
QString benchTableLine(const BenchRow &row);

// "default: gouraud at detail 25 % ..." for every scene in `rows`, fitted on
// the rows measured with the scene's own lights.
struct SceneFit {
    QString scene;
    BudgetFit fit;
    std::vector<BenchRow> rows; // the scene-light rows the fit chose from
};
std::vector<SceneFit> fitScenes(const std::vector<BenchRow> &rows, const ErrorBudget &budget);

// The per-object fit of every scene in `rows` that has per-object rows (at
// its own lights), from the rows alone: what `--from` can say without
// drawing anything.
struct SceneObjectFit {
    QString scene;
    ObjectFit fit;
};
std::vector<SceneObjectFit> fitObjectsByScene(const std::vector<BenchRow> &rows,
                                              const ErrorBudget &budget);

// fit.csv: one line per scene with the chosen model and its savings.
QString sceneFitsToCsv(const std::vector<SceneFit> &fits, const ErrorBudget &budget);

} // namespace phonglab
