#include "benchcli/BenchCommand.h"
#include "cli/common/CliCommon.h"
#include "cli/common/ProgramSynopsis.h"
#include "cli/dispatch/Cli.h"
#include "core/support/Language.h"
#include "core/support/RuntimeDirectory.h"
#include "ui/window/GuiMain.h"

int main(int argc, char **argv)
{
    phonglab::provideRuntimeDirectory(); // no Qt chatter about it on stderr
    // Any command and the window: `--lang en|de` anywhere on the line.
    if (const phonglab::LanguageOption language = phonglab::takeLanguageOption(argc, argv);
        !language.ok) {
        const QCoreApplication words(argc, argv); // the environment's language, for the message
        return phonglab::cli::usageError(phonglab::languageOptionError(language),
                                         phonglab::programSynopsis());
    }
    const phonglab::cli::Subcommand more[] = {phonglab::cli::kBenchSubcommand};
    if (const auto exitCode = phonglab::cli::dispatch(argc, argv, more))
        return *exitCode;
    return phonglab::runGui(argc, argv, phonglab::programSynopsis());
}
