#pragma once
#include "cli/Cli.h"

namespace phonglab::cli {

// phonglab bench [--scene FILE ...] [--quick] [--out DIR] [options]
// The speed-against-accuracy sweep; see `phonglab bench --help` and
// docs/speed-vs-accuracy.md.
int runBench(int argc, char **argv);

inline constexpr Subcommand kBenchSubcommand{
    "bench", "measure speed against accuracy of every shading method and detail", runBench};

} // namespace phonglab::cli
