#pragma once
#include "BuildQueue.h"
#include "KeptOutProgram.h"
#include "ShaderRecovery.h"
#include "ShadingChoice.h"
#include "core/scene/ShadingMethod.h"
#include "render/program/BuildWorker.h"
#include "render/program/ShaderSource.h"

#include <QElapsedTimer>
#include <QObject>
#include <memory>
#include <optional>

class QTimer;

namespace phonglab {

class BuildThread;
class ShaderDock;
class Viewport;
struct ProgramTrial;

// Live shader editing: connects the Shaders dock to the viewport. After an
// edit and a pause (QSettings "editor/debounceMs", 300 ms by default), and
// only when the text of the two stages really changed since the last build,
// it builds the program off the GUI thread (BuildThread), draws it once in
// the viewport's own context lent to that thread (the driver's draw-time
// compile happens there, not on the GUI thread) and then shows it; F5
// builds at once. That is the one build path: the others a benchmark
// compares it with live in the benchmark (bench_edit_latency). A failed build leaves the
// last good program running and puts each message on the user's line. The
// buffers are journaled (ShaderRecovery) before every build, and a sentinel
// marks a program that has not yet drawn a few frames. A program too slow
// to draw is kept out (KeptOutProgram); what the dock and the status bar
// say is worded in BuildStatusText.
class LiveShaderController : public QObject
{
    Q_OBJECT

public:
    // Where the path edit → build → first draw → shown stands. One program
    // is on that path at a time; a build asked for meanwhile is queued and
    // starts when the controller is Idle again.
    enum class State {
        WaitingForGl, // no GL context yet, or the view's is going (the window closes)
        Idle,         // the viewport draws the applied program; a build can start
        Building,     // the worker compiles and links the program
        Warming,      // the viewport's context is lent to the worker for the program's first draw
    };
    Q_ENUM(State)
    // Whether an edit builds after the pause, or only F5 does (recovered text
    // that crashed or hung a build last time).
    enum class AutoBuild {
        AfterPause,
        OnlyOnF5
    };

    LiveShaderController(ShaderDock *dock, Viewport *viewport, QObject *parent = nullptr);
    ~LiveShaderController() override; // a clean exit: stops the worker, clears the journal

    // The method the dock's text is of, chosen by the user or followed from
    // the scene; its changes ask this controller for builds.
    ShadingChoice *shading() const { return m_shading; }
    // F5: builds now, even unchanged or suspect text.
    void buildNow();

    // The dock holds text restored from a dead session's journal, from
    // `method`'s shaders (if known): AfterPause builds it now, OnlyOnF5 (it
    // crashed or hung a build last time) waits for F5.
    void takeRestoredText(std::optional<ShadingMethod> method, AutoBuild autoBuild);

    int debounceMs() const { return m_queue->debounceMs(); }
    // The build thread runs (false before GL is up, or when no context
    // could be shared with it: then edits are not built, and the dock says why).
    bool buildsOnWorker() const;
    State state() const { return m_state; }
    bool isBuilding() const { return m_state == State::Building || m_state == State::Warming; }
    bool isAutoBuildHeld() const { return m_autoBuild == AutoBuild::OnlyOnF5; }
    // An edit is waiting out the debounce; once it is not, the controller has
    // decided whether that text builds (isBuilding()) or not.
    bool isWaitingToBuild() const;
    QByteArray appliedHash() const { return m_appliedHash; }
    // The sources of the program the viewport draws with; none while it
    // draws the shipped program of its scene's shading (the live check draws
    // the frame again from these).
    const std::optional<StageSources> &appliedSources() const { return m_appliedSources; }
    // Timings of the program in use (warmNs > 0: warmed before it was shown).
    const BuildTimings &lastApplied() const { return m_lastApplied; }
    QByteArray currentHash() const;
    ShaderRecovery *recovery() const { return m_recovery; }
    // A program kept out for its frame time, waiting for "Apply anyway".
    bool hasKeptOutProgram() const { return m_keptOut->isWaiting(); }
    // Applies the program kept out (the dock's "Apply anyway").
    void applyKeptOut();

signals:
    // For the status bar.
    void statusMessage(const QString &text, int timeoutMs);
    // The viewport now draws with the program built from `hash`'s text.
    void programApplied(const QByteArray &hash, const phonglab::BuildTimings &timings);
    void buildFailed(const QByteArray &hash);
    // A new program built, but one frame of it would take `frameMs` or more,
    // more than the budget: it was not applied.
    void programKeptOut(double frameMs);
    void stateChanged(phonglab::LiveShaderController::State state);

private:
    void setUpTimers();
    void connectDock();
    void connectShadingChoice();
    void onTextEdited();
    void onGlInitialized();
    void onGlAboutToBeReleased();
    void onShippedProgramLoaded(ShadingMethod method);
    static bool mayGo(State from, State to);
    void setState(State state);
    bool startWorker();
    using BuildRequest = BuildQueue::Request;
    void requestBuild(BuildRequest request);
    void startQueuedBuild();
    void dispatch(const QByteArray &hash);
    void onBuilt(BuildReply reply);
    void finish(const QByteArray &hash, BuildReply reply);
    // A first draw on its way in the lent context, and what its end needs.
    struct WarmUp {
        quint64 serial = 0; // m_warmSerial when it started
        QByteArray hash;
        std::shared_ptr<GlProgram> program; // until the trial puts it in the renderer
        std::shared_ptr<ProgramTrial> trial;
        BuildReport report;
        BuildTimings timings;
    };
    bool warmInViewport(const QByteArray &hash, BuildReply &reply);
    void warmed(const WarmUp &warmUp, const Result<qint64> &warmNs);
    void announce(const QByteArray &hash, const BuildReport &result, const BuildTimings &timings);
    void takeBackContextNow();
    void showFailure(const BuildReport &result);

    ShaderDock *m_dock = nullptr;
    Viewport *m_viewport = nullptr;
    BuildThread *m_buildThread = nullptr;
    ShaderRecovery *m_recovery = nullptr;
    BuildQueue *m_queue = nullptr; // the debounce, the text last built, the request waiting
    QTimer *m_slowBuildNote = nullptr;
    QTimer *m_hangNote = nullptr; // a build or first draw that does not come back
    ShadingChoice *m_shading = nullptr;

    State m_state = State::WaitingForGl;
    AutoBuild m_autoBuild = AutoBuild::AfterPause;
    // A first draw in the lent viewport context failed once: later programs
    // are shown without it (their first frame compiles on the GUI thread).
    bool m_warmInViewport = true;
    QByteArray m_appliedHash; // text of the program the viewport draws with
    BuildTimings m_lastApplied;
    quint64 m_warmSerial = 0;    // counts warm-ups, so a late callback is told from the current one
    quint64 m_buildSerial = 0;   // while Building: the serial the worker's reply carries
    QByteArray m_buildHash;      // while Building or Warming: the text on its way
    StageSources m_buildSources; // ... and the sources it was built from
    std::optional<StageSources> m_appliedSources;
    // Freed by the next build, or applied anyway. Made in the constructor's
    // body, once the dock and the recovery it works with exist, whatever
    // order the members are declared in.
    std::unique_ptr<KeptOutProgram> m_keptOut;
    QElapsedTimer m_buildClock; // from dispatch to reply, for the status
};

} // namespace phonglab
