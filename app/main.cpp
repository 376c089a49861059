#include "benchcli/BenchCommand.h"
#include "cli/Cli.h"
#include "ui/window/GuiMain.h"

int main(int argc, char **argv)
{
    const phonglab::cli::Subcommand more[] = {phonglab::cli::kBenchSubcommand};
    if (const auto exitCode = phonglab::cli::dispatch(argc, argv, more))
        return *exitCode;
    return phonglab::runGui(argc, argv);
}
