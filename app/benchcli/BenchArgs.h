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
};

// The arguments of `phonglab bench`, or an exit code for usage errors and --help.
std::variant<BenchArgs, int> parseBenchArgs(const QStringList &arguments);

} // namespace phonglab::cli
