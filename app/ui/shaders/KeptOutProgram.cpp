#include "KeptOutProgram.h"

#include "BuildStatusText.h"
#include "ShaderDock.h"
#include "ShaderRecovery.h"

#include <utility>

namespace phonglab {

KeptOutProgram::KeptOutProgram(ShaderDock *dock, ShaderRecovery *recovery)
    : m_dock(dock)
    , m_recovery(recovery)
{
}

QString KeptOutProgram::keep(Built built, double frameMs, double budgetMs)
{
    // Never shown: as far as crash recovery goes, a build that failed.
    m_recovery->buildFailed();
    m_waiting = std::move(built);
    const QString text = BuildStatusText::keptOut(frameMs, budgetMs);
    m_dock->offerToApplyAnyway(text);
    return text;
}

std::optional<KeptOutProgram::Built> KeptOutProgram::take()
{
    return std::exchange(m_waiting, std::nullopt);
}

GlProgram KeptOutProgram::supersede()
{
    std::optional<Built> waiting = take();
    return waiting ? std::move(waiting->program) : GlProgram();
}

} // namespace phonglab
