#pragma once
#include "bench/BenchOptions.h"
#include "bench/ErrorBudget.h"

#include <QString>
#include <QStringList>
#include <variant>

namespace phonglab::cli {

struct BenchArgs {
    BenchOptions options;
    QString outDir;
    ErrorBudget budget;
    bool quick = false;
    bool normalStudy = false;
    QString fromCsv; // --from: fit and chart these results instead of measuring
    // --path: "orbit", "dolly" or a keyframe file; the path bench instead of the sweep.
    QString path;
    int pathFrames = 24; // --path-frames: frames of an orbit or a dolly
    bool sizeGiven = false;
    bool framesGiven = false;
};

// The arguments of `phonglab bench`, or an exit code for usage errors and --help.
std::variant<BenchArgs, int> parseBenchArgs(const QStringList &arguments);

} // namespace phonglab::cli
