#pragma once
#include "core/check/ShaderCheck.h"
#include "core/scene/Scene.h"
#include "render/check/CheckReportOutput.h"
#include "render/check/FrameRedraw.h"
#include "render/check/ProgramFindings.h"

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QImage>
#include <QObject>
#include <QThreadPool>
#include <atomic>
#include <memory>
#include <optional>

namespace phonglab {

// One finished check of the window's frame against the exact image: the
// verdict `phonglab check` gives on the same scene and files, found by the
// same steps (render/check/ProgramFindings, checkRender, nameWhatTheCodeDoes).
struct CheckedFrame {
    quint64 generation = 0; // of the request it answers
    Scene scene;            // as checked: the headlight included, the lights the program takes
    std::shared_ptr<const CheckReference> reference;
    QImage yours;   // the frame, without light markers, single-sampled
    QImage exact;   // the reference, 8-bit
    QImage heatmap; // checkHeatmap()
    // The verdict, the report, the bindings, the notes; errors where nothing
    // could be checked: a uniform nothing places, no surface in view.
    CheckOutcome outcome;
    std::vector<UnboundUniform> unbound; // the uniforms the user is to place, in the dock
    QString error;                       // the check itself could not run (no frame, no reference)
    double milliseconds = 0.0;           // request to result

    const CheckReport &report() const { return outcome.report; }
    bool hasVerdict() const { return outcome.verdict != Verdict::Error; }
};

// Runs checks off the GUI thread, one at a time; while one runs only the
// newest request waits (an older waiting one is dropped), and a running one
// that is still making the reference of another view is cancelled. Each
// check draws the frame again itself (FrameRedraw: single-sampled, in a
// context of its own on the check's thread), then compares. The reference
// is kept between checks of the same scene at the same size, so after a
// shader edit only the program's build, one draw and the comparison run; the
// meshes of the scene last checked are kept for its next view.
class CheckRunner : public QObject
{
    Q_OBJECT

public:
    explicit CheckRunner(QObject *parent = nullptr);
    ~CheckRunner() override;

    // On the GUI thread.
    void request(const FrameRecipe &frame);
    // Stops the running check as soon as it can (its result is dropped) and
    // forgets the waiting one: a scene load wants every core.
    void cancel();
    bool isBusy() const { return m_watcher.isRunning() || m_waiting.has_value(); }
    // The generation of the newest request: a result with another one
    // describes a frame that is no longer on screen.
    quint64 newestGeneration() const { return m_generation; }

signals:
    void finished(const phonglab::CheckedFrame &result);
    // How far the running check's exact image is, 0..99 %, as it moves (a
    // check that reuses the kept one has none to report).
    void progressed(int percent);

private:
    struct Request {
        quint64 generation = 0;
        FrameRecipe frame;
        QElapsedTimer clock;
    };
    struct Cache; // touched only by the one running job

    void start(Request request);
    void onFinished();

    // Its own pool, never Qt's global one: Qt paints and converts images on
    // the global pool's threads and waits for them on the GUI thread, so a
    // check occupying one there froze the window (a progress bar's paint
    // waited ~400 ms for a pool thread during a mesh load).
    QThreadPool m_pool;
    QFutureWatcher<CheckedFrame> m_watcher;
    std::optional<Request> m_waiting;
    std::optional<std::pair<Scene, QSize>> m_running; // what the running job checks
    std::shared_ptr<Cache> m_cache;
    // Where the check's context draws: made on this (the GUI) thread, as Qt
    // requires, and freed after the pool's thread let go of the context.
    std::unique_ptr<QOffscreenSurface> m_surface;
    quint64 m_generation = 0;
    std::shared_ptr<std::atomic<bool>> m_cancelled = std::make_shared<std::atomic<bool>>(false);
};

} // namespace phonglab
