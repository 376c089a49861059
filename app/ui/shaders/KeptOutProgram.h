#pragma once
#include "render/gl/SharedGlObject.h"
#include "render/program/BuildReport.h"
#include "render/program/BuildWorker.h"
#include "render/program/ShaderSource.h"

#include <QByteArray>
#include <QString>
#include <optional>

namespace phonglab {

class ShaderDock;
class ShaderRecovery;

// The kept-out policy: a new program whose frame would take longer than the
// budget (ProgramTrial) is not shown. The last good program keeps drawing,
// the Shaders dock says why and offers "Apply anyway", and the crash
// recovery counts it as a program that did not run. It waits, holding its GL
// program, until it is applied anyway or newer text supersedes it.
class KeptOutProgram
{
public:
    // A program built and tried, with what it was built from.
    struct Built {
        QByteArray hash; // of the text (programTextHash)
        GlProgram program;
        BuildReport report;
        BuildTimings timings;
        StageSources sources;
    };

    KeptOutProgram(ShaderDock *dock, ShaderRecovery *recovery);

    // Keeps `built` out, one frame of it taking `frameMs` or more, over
    // `budgetMs`; returns what the dock now says, for the status bar.
    QString keep(Built built, double frameMs, double budgetMs);
    bool isWaiting() const { return m_waiting.has_value(); }
    // The program waiting, once (the dock's "Apply anyway"); none when none waits.
    std::optional<Built> take();
    // Newer text is on its way: the program waiting, if any, for the caller
    // to free in a context of its share group (empty when none waited).
    GlProgram supersede();

private:
    ShaderDock *m_dock = nullptr;
    ShaderRecovery *m_recovery = nullptr;
    std::optional<Built> m_waiting;
};

} // namespace phonglab
