#pragma once
#include <QCoreApplication>
#include <memory>
#include <optional>
#include <span>

namespace phonglab::cli {

// The application object a command runs in, made before it reads its
// arguments: from then on the run speaks its language (core/support/Language), its
// usage errors included. `argc` must outlive it.
using MakeApplication = std::unique_ptr<QCoreApplication> (*)(int &argc, char **argv);
std::unique_ptr<QCoreApplication> makeCoreApplication(int &argc, char **argv);
std::unique_ptr<QCoreApplication> makeGuiApplication(int &argc, char **argv); // draws (GL)

struct Subcommand {
    const char *name;
    const char *summary; // one line in `phonglab --help`
    int (*run)(int argc, char **argv);
    MakeApplication makeApplication = makeCoreApplication;
};

// Runs a subcommand when argv names one (or --help / --version) and returns
// its exit code; nullopt means "no subcommand: start the GUI". `more` adds
// commands from libraries above this one (`bench`, which draws its charts
// with Qt Charts and so with widgets, which this library does not link);
// they follow this library's own in the help.
std::optional<int> dispatch(int argc, char **argv, std::span<const Subcommand> more = {});

} // namespace phonglab::cli
