#include "BuildStatusText.h"

#include "core/support/Language.h"

namespace phonglab {

namespace {

double toMs(qint64 ns)
{
    return double(ns) / 1e6;
}

} // namespace

QString BuildStatusText::compiling()
{
    return tr("Compiling…");
}

QString BuildStatusText::firstDrawHangs(int seconds)
{
    return tr("The new shader has not finished its first draw after %1 s (an endless loop?). "
              "It is marked: PhongLab will not run it by itself at the next start.")
        .arg(seconds);
}

QString BuildStatusText::liveEditingOff(const QString &reason)
{
    return tr("Live editing is off: no OpenGL context could be shared with the build thread "
              "(%1)")
        .arg(reason);
}

QString BuildStatusText::keptUnsavedEdits(ShadingMethod method)
{
    return tr("Kept your unsaved shader edits; the scene's %1 shading was not loaded (choose it "
              "in the Shaders dock to switch)")
        .arg(shadingName(method));
}

QString BuildStatusText::keptOut(double frameMs, double budgetMs)
{
    return tr("Kept out: one frame would take %1 ms or more (the budget is %2 ms, a few frames' "
              "worth); the last good program keeps drawing")
        .arg(sentenceNumber(frameMs, 'f', 0))
        .arg(sentenceNumber(budgetMs, 'f', 0));
}

QString BuildStatusText::compiled(double totalMs, const BuildTimings &timings, int warnings)
{
    QString status = tr("Compiled in %1 ms (compile %2, link %3, first draw %4)")
                         .arg(totalMs, 0, 'f', 0)
                         .arg(sentenceNumber(toMs(timings.compileNs), 'f', 0))
                         .arg(sentenceNumber(toMs(timings.linkNs), 'f', 0))
                         .arg(sentenceNumber(toMs(timings.warmNs), 'f', 0));
    if (warnings > 0)
        status += tr(" — %n warning(s)", nullptr, warnings);
    return status;
}

QString BuildStatusText::failed(int errors)
{
    return tr("%n error(s) — last good program still running", nullptr, errors);
}

} // namespace phonglab
