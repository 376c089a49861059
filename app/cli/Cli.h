#pragma once
#include <optional>

namespace phonglab::cli {

// Runs a subcommand when argv names one (or --help / --version) and returns
// its exit code; nullopt means "no subcommand: start the GUI".
std::optional<int> dispatch(int argc, char **argv);

} // namespace phonglab::cli
