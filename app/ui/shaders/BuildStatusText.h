#pragma once
#include "core/scene/ShadingMethod.h"
#include "render/program/BuildWorker.h"

#include <QCoreApplication>
#include <QString>

namespace phonglab {

// What live editing says in the Shaders dock and the status bar, worded in
// one place: a build on its way, its outcome, a program kept out, live
// editing off. LiveShaderController and KeptOutProgram decide when.
class BuildStatusText
{
    Q_DECLARE_TR_FUNCTIONS(phonglab::BuildStatusText)

public:
    // A build slower than a blink (said only then).
    static QString compiling();
    // A build or first draw that has not come back after `seconds`.
    static QString firstDrawHangs(int seconds);
    // No context could be shared with the build thread, for `reason`.
    static QString liveEditingOff(const QString &reason);
    // A scene opened with `method` while the dock holds unsaved edits.
    static QString keptUnsavedEdits(ShadingMethod method);
    // A program kept out: one frame would take `frameMs`, over `budgetMs`.
    static QString keptOut(double frameMs, double budgetMs);
    // A program applied: `totalMs` from the edit's build to the program
    // shown, its `timings` and how many warnings its build gave.
    static QString compiled(double totalMs, const BuildTimings &timings, int warnings);
    // A build that failed with `errors` errors.
    static QString failed(int errors);
};

} // namespace phonglab
