#include "CheckRunner.h"

#include "CheckPriority.h"
#include "mesh/loading/SceneMeshes.h"
#include "render/gl/GlFormat.h"
#include "render/gl/QtImages.h"

#include <QOffscreenSurface>
#include <QThread>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <exception>
#include <functional>

namespace phonglab {

namespace {

// A reference answers a scene exactly, folder included: relative mesh paths
// of two equal scenes in different folders name different files.
bool sameScene(const Scene &a, const Scene &b)
{
    return a == b && a.baseDir == b.baseDir;
}

} // namespace

struct CheckRunner::Cache {
    QHash<QString, std::shared_ptr<const MeshData>>
        meshes; // by meshKey(), of the scene last checked
    std::optional<Scene> scene;
    QSize size;
    std::shared_ptr<const CheckReference> reference;
    FrameRedraw redraw;

    // The meshes the redraw loaded, before it uploads them (and frees its
    // CPU copies), go to the exact image as well: loaded once, not twice.
    void keep(const SceneMeshes &loaded)
    {
        for (auto it = loaded.entries.cbegin(); it != loaded.entries.cend(); ++it)
            if (it->mesh)
                meshes.insert(it.key(), it->mesh);
    }

    // The meshes of every object, loading only those not kept already and
    // keeping no others.
    Result<std::vector<std::shared_ptr<const MeshData>>> objectMeshes(
        const Scene &s, const std::atomic<bool> &cancelled)
    {
        QSet<QString> kept;
        for (auto it = meshes.cbegin(); it != meshes.cend(); ++it)
            kept.insert(it.key());
        const SceneMeshes loaded =
            loadSceneMeshes(s, kept, [&](double) { return !cancelled.load(); });
        if (!loaded.ok())
            return fail(loaded.error);
        QHash<QString, std::shared_ptr<const MeshData>> used;
        std::vector<std::shared_ptr<const MeshData>> out;
        for (const SceneObject &object : s.objects) {
            const QString key = meshKey(s, object);
            std::shared_ptr<const MeshData> mesh = meshes.value(key);
            if (!mesh)
                mesh = loaded.entries.value(key).mesh;
            used.insert(key, mesh);
            out.push_back(mesh);
        }
        meshes = std::move(used);
        return out;
    }

    Result<std::shared_ptr<const CheckReference>> referenceFor(
        const Scene &s, QSize sz, const std::atomic<bool> &cancelled,
        const std::function<void(double)> &progress)
    {
        if (reference && scene && sameScene(*scene, s) && size == sz)
            return reference;
        reference.reset(); // not kept beside the new one while it is made
        const auto objectMeshes = this->objectMeshes(s, cancelled);
        if (!objectMeshes)
            return fail(objectMeshes.error());
        Result<CheckReference> made =
            makeCheckReference(s, *objectMeshes, sz.width(), sz.height(), [&](double f) {
                progress(f);
                return !cancelled.load();
            });
        if (!made)
            return fail(made.error());
        reference = std::make_shared<const CheckReference>(std::move(*made));
        scene = s;
        size = sz;
        return reference;
    }

    // The precision finding of a program, measured once: an orbit or a
    // light moved changes it by a step at most, and measuring builds and
    // draws the program a second time.
    PrecisionFinding precisionOf(const FrameRecipe &frame,
                                 const std::vector<ShaderStageText> &stages, const Scene &checked,
                                 const QImage &image)
    {
        QStringList key{QString::number(int(checked.course.precision))};
        for (const ShaderStageText &s : stages)
            key << s.text;
        if (!precision || precision->first != key)
            precision.emplace(key, redraw.measurePrecision(frame, stages, checked, image));
        return precision->second;
    }
    std::optional<std::pair<QStringList, PrecisionFinding>> precision;

    CheckedFrame check(const Request &request, QOffscreenSurface *surface,
                       const std::atomic<bool> &cancelled,
                       const std::function<void(double)> &progress);
    bool drawWhatIsChecked(const Request &request, QOffscreenSurface *surface,
                           const std::atomic<bool> &cancelled, CheckedFrame &result);
    void compare(const Request &request, const std::atomic<bool> &cancelled,
                 const std::function<void(double)> &progress, CheckedFrame &result);
};

namespace {

std::vector<ShaderStageText> stagesOf(const FrameRecipe &frame)
{
    if (!frame.sources)
        return {};
    return {{frame.sources->vertex.name, QString::fromUtf8(frame.sources->vertex.code), true},
            {frame.sources->fragment.name, QString::fromUtf8(frame.sources->fragment.code), false}};
}

// What nothing could place, as check's errors say it, with the window's way
// to place it.
void addPlacingErrors(CheckOutcome &outcome, const ProgramFindings &found)
{
    const auto error = [](const QString &message) {
        ShaderDiagnostic d;
        d.message = message;
        return d;
    };
    for (const QString &problem : found.problems)
        outcome.errors.push_back(error(problem));
    for (const UnboundUniform &unbound : found.unbound)
        outcome.errors.push_back(error(
            QObject::tr("%1: choose what it means in Uniforms").arg(unboundSentence(unbound))));
    for (const QString &conflict : found.conflicts)
        outcome.errors.push_back(error(conflict));
}

} // namespace

// The steps of drawForCheck() and checkDrawing() (cli/check/CheckSteps), on the
// window's frame: draw, find what the program bound, draw the lights it
// takes, compare, name what the code does.
CheckedFrame CheckRunner::Cache::check(const Request &request, QOffscreenSurface *surface,
                                       const std::atomic<bool> &cancelled,
                                       const std::function<void(double)> &progress)
{
    CheckedFrame result;
    result.generation = request.generation;
    result.scene = request.frame.scene;
    result.outcome.stages = stagesOf(request.frame);
    if (drawWhatIsChecked(request, surface, cancelled, result))
        compare(request, cancelled, progress, result);
    return result;
}

// Draws the frame and finds what its program bound; where it takes fewer
// lights than the scene has, draws those it takes. False where there is
// nothing to compare: the frame could not be drawn, or something is not
// placed (no verdict: PhongLab's gap, not the student's mistake).
bool CheckRunner::Cache::drawWhatIsChecked(const Request &request, QOffscreenSurface *surface,
                                           const std::atomic<bool> &cancelled, CheckedFrame &result)
{
    const auto keepGoing = [&] { return !cancelled.load(); };
    const auto keepMeshes = [&](const SceneMeshes &loaded) { keep(loaded); };
    Result<QImage> drawn = redraw.draw(request.frame, surface, keepGoing, keepMeshes);
    if (!drawn) {
        result.error = drawn.error();
        return false;
    }
    CheckOutcome &outcome = result.outcome;
    const ProgramFindings found = findProgramFindings(redraw.program(), request.frame.scene);
    outcome.bindings = found.bindings;
    outcome.notes << found.bindings.notes;
    result.unbound = found.unbound;
    addPlacingErrors(outcome, found);
    if (!outcome.errors.empty())
        return false;
    result.scene = found.checked;
    if (!found.lightsNote.isEmpty()) {
        outcome.notes << found.lightsNote;
        FrameRecipe lit = request.frame;
        lit.scene = found.checked;
        drawn = redraw.draw(lit, surface, keepGoing, keepMeshes);
        if (!drawn) {
            result.error = drawn.error();
            return false;
        }
    }
    result.yours = *drawn;
    return true;
}

// The drawn frame against the exact image of the scene checked: the
// verdict, the report, the precision, and the pictures of the overlay.
void CheckRunner::Cache::compare(const Request &request, const std::atomic<bool> &cancelled,
                                 const std::function<void(double)> &progress, CheckedFrame &result)
{
    Result<std::shared_ptr<const CheckReference>> made =
        referenceFor(result.scene, request.frame.size, cancelled, progress);
    if (!made) {
        result.error = made.error();
        return;
    }
    result.reference = *made;
    CheckOutcome &outcome = result.outcome;
    const RgbImage yours = toRgbImage(result.yours);
    outcome.report = checkRender(yours, *result.reference);
    if (request.frame.sources)
        nameWhatTheCodeDoes(outcome.report, request.frame.sources->vertex.code,
                            request.frame.sources->fragment.code);
    if (!outcome.report.comparable()) {
        ShaderDiagnostic d;
        d.message =
            QObject::tr("nothing to compare: no surface away from silhouettes in this view");
        outcome.errors.push_back(d);
        return;
    }
    outcome.verdict = outcome.report.passed() ? Verdict::Pass : Verdict::Fail;
    if (request.frame.sources)
        outcome.precision = precisionOf(request.frame, outcome.stages, result.scene, result.yours);
    // The exact image of the equation the frame was checked by: the slide's,
    // for a shader that matched it.
    const PhongEquation equation = outcome.report.equation;
    result.exact = equation == PhongEquation::Guarded
        ? toQImage(result.reference->exactImage)
        : toQImage(result.reference->exactOf(equation).toImage(result.scene.background));
    result.heatmap = toQImage(checkHeatmap(yours, *result.reference, equation));
}

CheckRunner::CheckRunner(QObject *parent)
    : QObject(parent)
    , m_cache(std::make_shared<Cache>())
{
    m_pool.setMaxThreadCount(1); // one check at a time; its ray casting has threads of its own
    // The check's GL context lives on the pool's one thread: it must never
    // be replaced by another.
    m_pool.setExpiryTimeout(-1);
    connect(&m_watcher, &QFutureWatcher<CheckedFrame>::finished, this, &CheckRunner::onFinished);
}

CheckRunner::~CheckRunner()
{
    // The job uses the cache, which goes with this: stop it early and wait.
    m_waiting.reset();
    m_cancelled->store(true);
    // The context goes on its own thread (the pool's one: queued behind the
    // running check), before its surface goes here. Never
    // QFuture::waitForFinished(), which runs a job not yet started on this
    // thread, and nothing between here and the last job that ends the
    // pool's thread (waitForDone() does).
    m_pool.start([cache = m_cache] { cache->redraw.destroy(); });
    m_pool.waitForDone();
}

void CheckRunner::request(const FrameRecipe &frame)
{
    if (!m_surface) {
        m_surface = std::make_unique<QOffscreenSurface>();
        m_surface->setFormat(phonglabSurfaceFormat(0));
        m_surface->create();
    }
    Request r{++m_generation, frame, {}};
    r.clock.start();
    if (!m_watcher.isRunning()) {
        start(std::move(r));
        return;
    }
    // Newest wins. A running job making the reference of another view is
    // wasted work; one checking the same view is nearly done.
    if (m_running && !(sameScene(m_running->first, frame.scene) && m_running->second == frame.size))
        m_cancelled->store(true);
    m_waiting = std::move(r);
}

void CheckRunner::cancel()
{
    m_waiting.reset();
    if (m_watcher.isRunning())
        m_cancelled->store(true);
}

void CheckRunner::start(Request request)
{
    std::shared_ptr<Cache> cache = m_cache;
    m_cancelled = std::make_shared<std::atomic<bool>>(false);
    m_running = std::make_pair(request.frame.scene, request.frame.size);
    m_watcher.setFuture(QtConcurrent::run(
        &m_pool,
        [this, cache, cancelled = m_cancelled, surface = m_surface.get(),
         request = std::move(request)]() {
            // How far the exact image is, in whole percent, to the GUI
            // thread when it moves (this outlives the job: ~CheckRunner waits).
            int shown = -1;
            const auto progress = [&](double fraction) {
                const int percent = std::clamp(int(100.0 * fraction), 0, 99);
                if (percent != shown) {
                    shown = percent;
                    QMetaObject::invokeMethod(
                        this, [this, percent] { emit progressed(percent); }, Qt::QueuedConnection);
                }
            };
            // Behind the window and a mesh load, but with a real share of the
            // processor beside busy programs (CheckPriority.h); the ray
            // casting's threads started from here inherit it.
            runAtCheckPriority();
            CheckedFrame result;
            if (cancelled->load()) {
                result.generation = request.generation;
                return result; // dropped by onFinished()
            }
            try {
                result = cache->check(request, surface, *cancelled, progress);
            } catch (
                const std::exception &e) { // std::bad_alloc on a huge view: a message, not a crash
                result = CheckedFrame{};
                result.generation = request.generation;
                result.scene = request.frame.scene;
                result.error =
                    QObject::tr("the check failed: %1").arg(QString::fromLocal8Bit(e.what()));
                cache->reference.reset();
            }
            result.milliseconds = double(request.clock.nsecsElapsed()) / 1e6;
            return result;
        }));
}

void CheckRunner::onFinished()
{
    const CheckedFrame result = m_watcher.result();
    const bool cancelled = m_cancelled->load();
    m_running.reset();
    if (m_waiting) {
        Request next = std::move(*m_waiting);
        m_waiting.reset();
        start(std::move(next));
        return; // a newer request supersedes this result
    }
    if (!cancelled)
        emit finished(result);
}

} // namespace phonglab
