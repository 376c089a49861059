#include "ShaderChecker.h"

#include "mesh/SceneMeshes.h"

#include <QScopeGuard>
#include <QThread>
#include <QtConcurrent/QtConcurrentRun>

namespace phonglab {

struct ShaderChecker::Cache {
    QHash<QString, std::shared_ptr<const MeshData>> meshes; // by meshKey()
    std::optional<Scene> scene;
    QSize size;
    std::shared_ptr<const CheckReference> reference;

    // The meshes of every object, loading only those not kept already.
    std::optional<std::vector<std::shared_ptr<const MeshData>>> objectMeshes(const Scene &s, QString *error)
    {
        QSet<QString> kept;
        for (auto it = meshes.cbegin(); it != meshes.cend(); ++it)
            kept.insert(it.key());
        const SceneMeshes loaded = loadSceneMeshes(s, kept);
        if (!loaded.ok()) {
            *error = loaded.error;
            return std::nullopt;
        }
        for (auto it = loaded.entries.cbegin(); it != loaded.entries.cend(); ++it)
            if (it->mesh)
                meshes.insert(it.key(), it->mesh);
        std::vector<std::shared_ptr<const MeshData>> out;
        for (const SceneObject &object : s.objects)
            out.push_back(meshes.value(meshKey(s, object)));
        return out;
    }

    std::shared_ptr<const CheckReference> referenceFor(const Scene &s, QSize sz, QString *error,
                                                       const std::atomic<bool> &cancelled)
    {
        if (reference && scene && *scene == s && size == sz)
            return reference;
        const auto objectMeshes = this->objectMeshes(s, error);
        if (!objectMeshes)
            return nullptr;
        std::optional<CheckReference> made = makeCheckReference(s, *objectMeshes, sz.width(), sz.height(), error,
                                                             [&](double) { return !cancelled.load(); });
        if (!made)
            return nullptr;
        reference = std::make_shared<const CheckReference>(std::move(*made));
        scene = s;
        size = sz;
        return reference;
    }
};

ShaderChecker::ShaderChecker(QObject *parent)
    : QObject(parent)
    , m_cache(std::make_shared<Cache>())
{
    m_pool.setMaxThreadCount(1); // one check at a time; its ray casting has threads of its own
    connect(&m_watcher, &QFutureWatcher<CheckResult>::finished, this, &ShaderChecker::onFinished);
}

ShaderChecker::~ShaderChecker()
{
    // The job uses the cache, which goes with this: stop it early and wait.
    m_waiting.reset();
    m_cancelled->store(true);
    m_watcher.waitForFinished();
}

void ShaderChecker::request(const Scene &scene, const QImage &yours)
{
    Request r{++m_generation, scene, yours, {}};
    r.clock.start();
    if (m_watcher.isRunning())
        m_waiting = std::move(r); // newest wins
    else
        start(std::move(r));
}

void ShaderChecker::cancel()
{
    m_waiting.reset();
    if (m_watcher.isRunning())
        m_cancelled->store(true);
}

void ShaderChecker::start(Request request)
{
    std::shared_ptr<Cache> cache = m_cache;
    m_cancelled = std::make_shared<std::atomic<bool>>(false);
    m_watcher.setFuture(QtConcurrent::run(&m_pool, [cache, cancelled = m_cancelled, request = std::move(request)]() {
        // Background work must never take a core from the window or a mesh
        // load: idle priority (SCHED_IDLE on Linux), which the ray-casting
        // threads started from here inherit. The pool thread is reused, so
        // its priority is put back afterwards.
        QThread::currentThread()->setPriority(QThread::IdlePriority);
        const auto restore = qScopeGuard([] { QThread::currentThread()->setPriority(QThread::NormalPriority); });
        CheckResult result;
        result.generation = request.generation;
        result.scene = request.scene;
        result.yours = request.yours;
        result.reference = cache->referenceFor(request.scene, request.yours.size(), &result.error, *cancelled);
        if (result.reference) {
            result.report = checkRender(request.yours, *result.reference);
            result.exact = result.reference->exactImage;
            result.heatmap = checkHeatmap(request.yours, *result.reference);
        }
        result.milliseconds = double(request.clock.nsecsElapsed()) / 1e6;
        return result;
    }));
}

void ShaderChecker::onFinished()
{
    const CheckResult result = m_watcher.result();
    if (m_cancelled->load()) {
        if (m_waiting) {
            Request next = std::move(*m_waiting);
            m_waiting.reset();
            start(std::move(next));
        }
        return;
    }
    if (m_waiting) {
        Request next = std::move(*m_waiting);
        m_waiting.reset();
        start(std::move(next));
        return; // a newer request supersedes this result
    }
    emit finished(result);
}

} // namespace phonglab
