#include "SceneLoadJob.h"

#include "ui/viewport/Viewport.h"

#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>
#include <exception>
#include <utility>

namespace phonglab {

namespace {

constexpr int kProgressSteps = 1000;

// Runs on a pool thread: no GL, no widgets, only its own copies.
void loadInBackground(QPromise<SceneMeshes> &promise, const Scene &scene, const QSet<QString> &skip,
                      const std::shared_ptr<std::atomic_bool> &cancelRequested)
{
    promise.setProgressRange(0, kProgressSteps);
    const LoadProgress progress = [&promise, &cancelRequested](double fraction) {
        // QFutureWatcher delivers this queued (and throttled) on the GUI thread.
        promise.setProgressValue(qBound(0, int(fraction * kProgressSteps), kProgressSteps));
        return !cancelRequested->load();
    };
    promise.addResult(loadSceneMeshes(scene, skip, progress));
}

} // namespace

SceneLoadJob::SceneLoadJob(Viewport *viewport, QObject *parent)
    : QObject(parent)
    , m_viewport(viewport)
{
}

SceneLoadJob::~SceneLoadJob()
{
    if (!m_watcher)
        return;
    // The worker reads nothing of ours, but stopping it here keeps a closed
    // window from leaving a load running behind it.
    m_cancelRequested->store(true);
    m_watcher->disconnect(this);
    m_watcher->waitForFinished();
}

void SceneLoadJob::start(SceneLoadRequest request)
{
    const bool supersedes = isRunning();
    const QString superseded = m_request.label;
    if (supersedes)
        abandonWorker();
    m_request = std::move(request);
    m_cancelRequested = std::make_shared<std::atomic_bool>(false);
    m_watcher = new QFutureWatcher<SceneMeshes>(this);
    connect(m_watcher, &QFutureWatcherBase::progressValueChanged, this,
            [this](int value) { emit progressChanged(double(value) / kProgressSteps); });
    connect(m_watcher, &QFutureWatcherBase::finished, this, &SceneLoadJob::workerFinished);
    m_watcher->setFuture(QtConcurrent::run(loadInBackground, m_request.scene,
                                           m_viewport->loadedKeys(), m_cancelRequested));
    // Reported with the new load already running, so that listeners can tell
    // a superseded load from one the user cancelled.
    if (supersedes)
        emit cancelled(superseded);
    emit started(m_request.label);
}

void SceneLoadJob::cancel()
{
    if (!isRunning())
        return;
    // Reported at once rather than when the worker notices: the window is
    // back to its old scene either way.
    const QString label = m_request.label;
    abandonWorker();
    m_request = {};
    emit cancelled(label);
}

void SceneLoadJob::finishNow()
{
    if (!isRunning())
        return;
    // Its finished() and any progress still queued must not come again.
    m_watcher->disconnect(this);
    m_watcher->waitForFinished();
    workerFinished();
}

// The worker stops at its next progress report; until then it runs on
// unobserved, and its watcher goes when it ends.
void SceneLoadJob::abandonWorker()
{
    m_cancelRequested->store(true);
    m_watcher->disconnect(this);
    if (m_watcher->isFinished())
        m_watcher->deleteLater();
    else
        connect(m_watcher, &QFutureWatcherBase::finished, m_watcher, &QObject::deleteLater);
    m_watcher = nullptr;
}

void SceneLoadJob::workerFinished()
{
    QFutureWatcher<SceneMeshes> *watcher = std::exchange(m_watcher, nullptr);
    watcher->deleteLater();
    // Slots connected to the signals below may start the next load.
    const SceneLoadRequest request = std::exchange(m_request, {});

    SceneMeshes meshes;
    try {
        meshes = watcher->future().takeResult();
    } catch (const std::exception &e) { // e.g. std::bad_alloc on a huge file
        emit failed(request.label, tr("loading stopped: %1").arg(QString::fromLocal8Bit(e.what())));
        return;
    }
    if (!meshes.ok()) {
        emit failed(request.label, meshes.error);
        return;
    }

    Scene scene = request.scene;
    if (request.finish) {
        SceneLoadRequest::MeshInfo info = m_viewport->meshInfo();
        for (auto it = meshes.entries.cbegin(); it != meshes.entries.cend(); ++it)
            info.insert(it.key(), it.value());
        scene = request.finish(m_viewport->currentScene(), info);
    }
    if (const Result<> set = m_viewport->setScene(scene, std::move(meshes)); !set) {
        emit failed(request.label, set.error());
        return;
    }
    if (request.shown)
        request.shown();
    emit loaded(request.label);
}

} // namespace phonglab
