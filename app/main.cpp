#include "cli/Cli.h"
#include "ui/GuiMain.h"

int main(int argc, char **argv)
{
    if (const auto exitCode = phonglab::cli::dispatch(argc, argv))
        return *exitCode;
    return phonglab::runGui(argc, argv);
}
