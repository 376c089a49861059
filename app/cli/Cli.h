#pragma once
#include <optional>
#include <span>

namespace phonglab::cli {

struct Subcommand {
    const char *name;
    const char *summary; // one line in `phonglab --help`
    int (*run)(int argc, char **argv);
};

// Runs a subcommand when argv names one (or --help / --version) and returns
// its exit code; nullopt means "no subcommand: start the GUI". `more` adds
// commands from libraries above this one (`bench`, which draws its charts
// with Qt Charts and so with widgets, which this library does not link);
// they follow this library's own in the help.
std::optional<int> dispatch(int argc, char **argv, std::span<const Subcommand> more = {});

} // namespace phonglab::cli
