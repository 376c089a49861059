#pragma once
#include "cli/dispatch/Cli.h"
#include <QtGlobal>

namespace phonglab::cli {

// phonglab bench [--scene FILE ...] [--quick] [--out DIR] [options]
// The speed-against-accuracy sweep; see `phonglab bench --help` and
// docs/speed-vs-accuracy.md.
int runBench(int argc, char **argv);
// A QApplication: Qt Charts draws with widgets.
std::unique_ptr<QCoreApplication> makeWidgetsApplication(int &argc, char **argv);

inline constexpr Subcommand kBenchSubcommand{
    "bench",
    // Translated where `phonglab --help` prints it (cli/dispatch/Cli.cpp).
    QT_TRANSLATE_NOOP("phonglab::cli::Cli",
                      "measure speed against accuracy of every shading method and detail"),
    runBench, makeWidgetsApplication};

} // namespace phonglab::cli
