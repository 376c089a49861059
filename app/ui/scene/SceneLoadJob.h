#pragma once
#include "core/scene/Scene.h"
#include "mesh/loading/SceneMeshes.h"

#include <QFutureWatcher>
#include <QObject>
#include <atomic>
#include <functional>
#include <memory>

namespace phonglab {

class Viewport;

// What to load, and how to show it once loaded.
struct SceneLoadRequest {
    using MeshInfo = QHash<QString, SceneMeshes::Entry>;

    Scene scene;   // whose meshes are loaded
    QString label; // names the load in the progress bar and in messages
    // Builds the scene to show from the one on screen when loading ends (so
    // camera moves made meanwhile are kept) and the stats of every mesh
    // `scene` uses, by meshKey(). Unset: `scene` is shown as it is.
    std::function<Scene(const Scene &shown, const MeshInfo &meshes)> finish;
    // Runs once the viewport shows the new scene, before loaded() is emitted.
    std::function<void()> shown;
};

// Loads a scene's meshes on a worker thread, then has the Viewport upload
// them (on the GUI thread, which owns the GL context) and switch. Meanwhile
// the window stays responsive and the old scene keeps rendering. One load at
// a time: starting another cancels the one running.
class SceneLoadJob : public QObject
{
    Q_OBJECT

public:
    explicit SceneLoadJob(Viewport *viewport, QObject *parent = nullptr);
    ~SceneLoadJob() override;

    void start(SceneLoadRequest request);
    // Waits on this thread for the running load's worker, then ends the load
    // here (shown, loaded() or failed()) instead of at a later turn of the
    // event loop: for start-up and tests, which go on with the scene shown.
    void finishNow();
    bool isRunning() const { return m_watcher != nullptr; }
    QString label() const { return m_request.label; }

public slots:
    // The old scene stays; cancelled() follows once the worker has stopped.
    void cancel();

signals:
    void started(const QString &label);
    void progressChanged(double fraction);                   // 0 to 1
    void loaded(const QString &label);                       // the viewport shows the new scene
    void failed(const QString &label, const QString &error); // the old scene stays
    void cancelled(const QString &label);

private:
    void workerFinished();
    void abandonWorker();

    Viewport *m_viewport = nullptr;
    SceneLoadRequest m_request;
    // Shared with the worker, which outlives this job's interest in it when
    // a newer load supersedes it.
    std::shared_ptr<std::atomic_bool> m_cancelRequested;
    QFutureWatcher<SceneMeshes> *m_watcher = nullptr; // the running load
};

} // namespace phonglab
