#include "LiveShaderController.h"

#include "BuildStatusText.h"
#include "ProgramTrial.h"
#include "ShaderDock.h"
#include "ShaderFileSet.h"
#include "ShaderRecovery.h"
#include "core/session/RecoveryJournal.h"
#include "render/program/BuildThread.h"
#include "ui/viewport/Viewport.h"

#include <QSettings>
#include <QTimer>
#include <atomic>
#include <cassert>

namespace phonglab {

namespace {

constexpr int kDefaultDebounceMs = 300;
constexpr int kStatusTimeoutMs = 8000;
constexpr int kSlowBuildNoteMs = 250;
constexpr int kHangNoteMs = 5000;

// The text hash of what the viewport builds for `method` by itself.
QByteArray shippedHash(ShadingMethod method)
{
    const StageSources shipped = readShippedStages(method).valueOr(StageSources{});
    return programTextHash(shipped.vertex.code, shipped.fragment.code);
}

} // namespace

LiveShaderController::LiveShaderController(ShaderDock *dock, Viewport *viewport, QObject *parent)
    : QObject(parent)
    , m_dock(dock)
    , m_viewport(viewport)
    , m_buildThread(new BuildThread(this))
    , m_recovery(new ShaderRecovery(dock, this))
    , m_queue(new BuildQueue(
          QSettings().value(QStringLiteral("editor/debounceMs"), kDefaultDebounceMs).toInt(), this))
    , m_slowBuildNote(new QTimer(this))
    , m_hangNote(new QTimer(this))
{
    m_keptOut = std::make_unique<KeptOutProgram>(m_dock, m_recovery);
    setUpTimers();
    m_buildThread->setReceiver([this](BuildReply reply) { onBuilt(std::move(reply)); });
    connect(m_viewport, &Viewport::glInitialized, this, &LiveShaderController::onGlInitialized);
    connect(m_viewport, &Viewport::glAboutToBeReleased, this,
            &LiveShaderController::onGlAboutToBeReleased);
    connect(m_viewport, &Viewport::frameRendered, m_recovery, &ShaderRecovery::frameRendered);
    connect(m_viewport, &Viewport::shippedProgramLoaded, this,
            &LiveShaderController::onShippedProgramLoaded);
    connectDock();
    // After the dock's connections: the scene's shipped shaders it shows
    // reach the journal as the dock's files (ShaderFileSet::dirtyChanged).
    m_shading = new ShadingChoice(m_dock, m_recovery, m_viewport, this);
    connectShadingChoice();
}

void LiveShaderController::setUpTimers()
{
    connect(m_queue, &BuildQueue::pauseOver, this, [this] { requestBuild(BuildRequest::NewText); });
    // Said only when a build is slow: relaying out the dock for a status that
    // lasts 3 ms would cost the GUI thread more than the build itself.
    m_slowBuildNote->setSingleShot(true);
    m_slowBuildNote->setInterval(kSlowBuildNoteMs);
    connect(m_slowBuildNote, &QTimer::timeout, this,
            [this] { m_dock->setCompileStatus(BuildStatusText::compiling(), true); });
    m_hangNote->setSingleShot(true);
    m_hangNote->setInterval(kHangNoteMs);
    connect(m_hangNote, &QTimer::timeout, this, [this] {
        const QString text = BuildStatusText::firstDrawHangs(kHangNoteMs / 1000);
        m_dock->setCompileStatus(text, false);
        emit statusMessage(text, 0);
    });
}

LiveShaderController::~LiveShaderController()
{
    m_buildThread->stop();
    takeBackContextNow();
    m_recovery->clear();
}

void LiveShaderController::connectDock()
{
    connect(m_dock, &ShaderDock::textEdited, this, &LiveShaderController::onTextEdited);
    connect(m_dock, &ShaderDock::compileRequested, this, &LiveShaderController::buildNow);
    connect(m_dock, &ShaderDock::applyAnywayRequested, this, &LiveShaderController::applyKeptOut);
    connect(m_dock, &ShaderDock::filesChanged, m_recovery, &ShaderRecovery::noteFilesChanged);
    connect(m_dock->files(), &ShaderFileSet::dirtyChanged, m_recovery,
            &ShaderRecovery::noteFilesChanged);
}

QByteArray LiveShaderController::currentHash() const
{
    return programTextHash(m_dock->text(ShaderStage::Vertex), m_dock->text(ShaderStage::Fragment));
}

bool LiveShaderController::buildsOnWorker() const
{
    return m_buildThread->isRunning();
}

void LiveShaderController::connectShadingChoice()
{
    connect(m_shading, &ShadingChoice::chosen, this, [this] {
        m_autoBuild = AutoBuild::AfterPause;
        requestBuild(BuildRequest::Always);
    });
    connect(m_shading, &ShadingChoice::followedScene, this, [this] {
        m_appliedHash = currentHash();
        m_queue->setLastBuilt(m_appliedHash);
        m_appliedSources.reset();
    });
    connect(m_shading, &ShadingChoice::editsKept, this, [this](ShadingMethod sceneMethod) {
        emit statusMessage(BuildStatusText::keptUnsavedEdits(sceneMethod), kStatusTimeoutMs);
        if (m_autoBuild == AutoBuild::AfterPause)
            requestBuild(BuildRequest::Always);
    });
}

void LiveShaderController::buildNow()
{
    m_queue->stopPause();
    m_autoBuild = AutoBuild::AfterPause;
    requestBuild(BuildRequest::Always);
}

bool LiveShaderController::isWaitingToBuild() const
{
    return m_queue->isPausing();
}

void LiveShaderController::takeRestoredText(std::optional<ShadingMethod> method,
                                            AutoBuild autoBuild)
{
    if (method)
        m_shading->takeRestored(*method); // the method the restored buffers came from
    m_autoBuild = autoBuild;
    m_queue->stopPause(); // restoring typed the text in again; build it once, below
    if (autoBuild == AutoBuild::AfterPause)
        requestBuild(BuildRequest::NewText);
}

void LiveShaderController::onTextEdited()
{
    m_recovery->noteEdited();
    if (m_autoBuild == AutoBuild::AfterPause)
        m_queue->edited();
}

void LiveShaderController::onGlInitialized()
{
    // The viewport has just built its scene's shipped program itself.
    m_appliedHash = shippedHash(m_viewport->currentScene().shading);
    m_queue->setLastBuilt(m_appliedHash);
    m_appliedSources.reset();
    if (!startWorker())
        return; // WaitingForGl: edits wait, as before GL was up
    setState(State::Idle);
    const bool wanted = m_queue->takeWaiting().has_value();
    if (m_autoBuild == AutoBuild::OnlyOnF5)
        return;
    if (wanted || currentHash() != m_appliedHash)
        requestBuild(BuildRequest::NewText);
}

// The viewport replaced the program with a shipped one. For another
// method (a scene was opened) ShadingChoice::followScene() comes next and decides;
// for the dock's own method (a failed open put it back) the dock's text is
// built again if it differs.
void LiveShaderController::onShippedProgramLoaded(ShadingMethod method)
{
    m_appliedHash = shippedHash(method);
    m_queue->setLastBuilt(m_appliedHash);
    m_appliedSources.reset();
    if (method == m_shading->method() && m_autoBuild == AutoBuild::AfterPause
        && currentHash() != m_appliedHash)
        requestBuild(BuildRequest::NewText);
}

void LiveShaderController::onGlAboutToBeReleased()
{
    // The worker's context shares with the view's, which goes with the view
    // (the window is closing): nothing is built from here on.
    m_buildThread->stop();
    takeBackContextNow();
    setState(State::WaitingForGl);
    m_queue->forgetWaiting();
    m_slowBuildNote->stop();
    m_hangNote->stop();
}

// The worker has stopped: a context lent to it is back, even if its reply is lost.
void LiveShaderController::takeBackContextNow()
{
    if (m_state != State::Warming)
        return;
    setState(State::Idle);
    m_viewport->glContext().takeBackContext(0);
}

// The machine's transitions: WaitingForGl is entered from anywhere (the
// view's context goes) and left only to Idle; a build starts from Idle and
// ends in Idle; a first draw starts from Idle and ends in Idle.
bool LiveShaderController::mayGo(State from, State to)
{
    switch (to) {
    case State::WaitingForGl: return true;
    case State::Idle: return true;
    case State::Building: return from == State::Idle;
    case State::Warming: return from == State::Idle;
    }
    return false;
}

void LiveShaderController::setState(State state)
{
    assert(mayGo(m_state, state));
    if (std::exchange(m_state, state) != state)
        emit stateChanged(state);
}

// Without a worker no edit is built: the dock says why, and the viewport
// keeps drawing the scene's shipped program.
bool LiveShaderController::startWorker()
{
    if (const Result<> started = m_buildThread->start(m_viewport->glContext().context());
        !started) {
        qWarning("phonglab: shaders cannot be built off the GUI thread: %s",
                 qPrintable(started.error()));
        const QString text = BuildStatusText::liveEditingOff(started.error());
        m_dock->setCompileStatus(text, false);
        emit statusMessage(text, 0);
        return false;
    }
    qInfo("phonglab: shaders build on a worker thread with a shared context; "
          "GL_KHR_parallel_shader_compile: %s",
          m_buildThread->hasParallelShaderCompile() ? "available" : "not available");
    return true;
}

void LiveShaderController::requestBuild(BuildRequest request)
{
    const BuildQueue::Builder builder = m_state == State::WaitingForGl ? BuildQueue::Builder::NoGl
        : m_state == State::Idle                                       ? BuildQueue::Builder::Ready
                                                                       : BuildQueue::Builder::Busy;
    const QByteArray hash = currentHash();
    if (m_queue->decide(request, hash, builder) == BuildQueue::Decision::Build)
        dispatch(hash);
}

void LiveShaderController::startQueuedBuild()
{
    if (const std::optional<BuildRequest> waiting = m_queue->takeWaiting())
        requestBuild(*waiting);
}

void LiveShaderController::dispatch(const QByteArray &hash)
{
    // Both before the program exists: a crash in the compiler, or in the
    // warm-up draw, then leaves the text in the journal and marked suspect.
    m_recovery->writeNow();
    m_recovery->buildStarted(hash);
    if (GlProgram superseded = m_keptOut->supersede())
        m_buildThread->release(std::move(superseded));
    m_queue->setLastBuilt(hash);
    const ShaderSource vertex{m_dock->filePath(ShaderStage::Vertex),
                              m_dock->text(ShaderStage::Vertex)};
    const ShaderSource fragment{m_dock->filePath(ShaderStage::Fragment),
                                m_dock->text(ShaderStage::Fragment)};
    m_buildClock.start();
    m_buildHash = hash;
    m_buildSources = {vertex, fragment};
    setState(State::Building);
    const Scene &scene = m_viewport->currentScene();
    m_buildSerial = m_buildThread->build(vertex, fragment, 0, scene.bindings, scene.course);
    m_slowBuildNote->start();
    m_hangNote->start();
}

void LiveShaderController::onBuilt(BuildReply reply)
{
    // A reply from before a restart of the worker, or for a build superseded.
    if (m_state != State::Building || reply.serial != m_buildSerial) {
        m_buildThread->release(std::move(reply.program));
        return;
    }
    setState(State::Idle);
    m_slowBuildNote->stop();
    // Even when newer text waits, a finished program is shown: steady
    // progress while someone keeps typing in bursts longer than a build.
    finish(m_buildHash, std::move(reply));
    if (m_state == State::Idle)
        startQueuedBuild(); // else once the first draw is done
}

void LiveShaderController::finish(const QByteArray &hash, BuildReply reply)
{
    if (!reply.program) {
        m_hangNote->stop();
        showFailure(reply.report);
        m_recovery->buildFailed();
        emit buildFailed(hash);
        return;
    }
    m_dock->showDiagnostics(reply.report.diagnostics); // warnings only; clears old errors
    if (warmInViewport(hash, reply))
        return; // the hang note now waits for the draw in the lent context
    m_hangNote->stop();
    m_viewport->program().adopt(std::move(reply.program));
    announce(hash, reply.report, reply.timings);
}

// The switch to the new program and its first draw, in the viewport's own
// context lent to the worker: where the driver keeps draw-time variants and
// per-program state per context (llvmpipe), this is the only way that work
// stays off the GUI thread.
// Takes reply.program when it returns true.
bool LiveShaderController::warmInViewport(const QByteArray &hash, BuildReply &reply)
{
    if (!m_warmInViewport)
        return false;
    std::optional<LentContext> lent =
        m_viewport->glContext().lendContext(m_buildThread->workerThread());
    if (!lent)
        return false;
    // The GUI thread leaves the renderer alone while the context is lent.
    // The program goes to the renderer on the worker thread, with the lent
    // context current; if it never got that far, here, once it is back.
    const GLuint programId = reply.program.id();
    WarmUp warmUp{
        ++m_warmSerial, hash,         std::make_shared<GlProgram>(std::move(reply.program)),
        nullptr,        reply.report, reply.timings};
    // A trial first: over the budget the new program comes out again and the
    // last good one keeps drawing.
    warmUp.trial = ProgramTrial::arm(*lent, m_viewport, warmUp.program);
    setState(State::Warming);
    m_buildThread->warmInLentContext(
        *lent, programId, [this, warmUp](const Result<qint64> &warmNs) { warmed(warmUp, warmNs); });
    return true;
}

// The lent context's first draw is over (`warmNs`: how long it took, or why
// it could not be made there).
void LiveShaderController::warmed(const WarmUp &warmUp, const Result<qint64> &warmNs)
{
    // The context went away meanwhile (and came back with it), or this is an
    // older warm-up.
    if (m_state != State::Warming || warmUp.serial != m_warmSerial)
        return;
    setState(State::Idle);
    m_hangNote->stop();
    m_viewport->glContext().takeBackContext();
    const ProgramTrial &trial = *warmUp.trial;
    if (trial.keptOut()) {
        const QString text = m_keptOut->keep({warmUp.hash, std::move(*warmUp.program),
                                              warmUp.report, warmUp.timings, m_buildSources},
                                             trial.frameMs, trial.budgetMs);
        emit programKeptOut(trial.frameMs);
        emit statusMessage(text, kStatusTimeoutMs);
        startQueuedBuild();
        return;
    }
    if (*warmUp.program) // the trial never ran: the context could not be had there
        m_viewport->program().adopt(std::move(*warmUp.program));
    BuildTimings timings = warmUp.timings;
    if (warmNs) {
        timings.warmNs = *warmNs;
    } else {
        qWarning("phonglab: warming programs in the viewport's context is off: %s",
                 qPrintable(warmNs.error()));
        m_warmInViewport = false;
    }
    announce(warmUp.hash, warmUp.report, timings);
    startQueuedBuild();
}

void LiveShaderController::applyKeptOut()
{
    if (m_state != State::Idle)
        return;
    std::optional<KeptOutProgram::Built> kept = m_keptOut->take();
    if (!kept)
        return;
    m_viewport->program().adopt(std::move(kept->program));
    m_buildSources = kept->sources;
    announce(kept->hash, kept->report, kept->timings);
}

void LiveShaderController::announce(const QByteArray &hash, const BuildReport &result,
                                    const BuildTimings &timings)
{
    m_appliedHash = hash;
    m_appliedSources = m_buildSources;
    m_lastApplied = timings;
    m_recovery->programShown(hash);
    m_dock->setCompileStatus(BuildStatusText::compiled(double(m_buildClock.nsecsElapsed()) / 1e6,
                                                       timings, int(result.diagnostics.size())),
                             true);
    emit programApplied(hash, timings);
}

void LiveShaderController::showFailure(const BuildReport &result)
{
    m_dock->showDiagnostics(result.diagnostics);
    int errors = 0;
    for (const ShaderDiagnostic &d : result.diagnostics)
        errors += d.isError();
    const QString text = BuildStatusText::failed(errors);
    m_dock->setCompileStatus(text, false);
    emit statusMessage(text, kStatusTimeoutMs);
}

} // namespace phonglab
