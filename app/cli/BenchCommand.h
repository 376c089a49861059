#pragma once

namespace phonglab::cli {

// phonglab bench [--scene FILE ...] [--quick] [--out DIR] [options]
// The speed-against-accuracy sweep; see `phonglab bench --help` and
// docs/speed-vs-accuracy.md.
int runBench(int argc, char **argv);

} // namespace phonglab::cli
