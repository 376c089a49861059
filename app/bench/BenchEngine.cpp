#include "BenchEngine.h"

#include "BenchPictures.h"
#include "LightSetups.h"
#include "ObjectFit.h"
#include "core/reference/AnalyticRaycaster.h"
#include "core/reference/ImageMetrics.h"
#include "core/reference/MeshRaycaster.h"
#include "core/reference/ReferenceEdges.h"
#include "core/reference/SceneHits.h"
#include "core/scene/SceneJson.h"
#include "mesh/import/BuiltinMeshes.h"
#include "mesh/loading/SceneMeshes.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/QtImages.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>

#include <algorithm>
#include <set>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct BenchEngineWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::BenchEngine)
};

struct BenchEngine::SceneRun {
    QString name;
    Scene scene;
    std::vector<std::shared_ptr<const MeshData>> fullMeshes; // per object; null = analytic builtin
    std::vector<int> lightCounts;
    int ownLights = 0;
    std::vector<ReferenceImage> references; // per light count
    std::vector<std::uint8_t> compared; // 1 away from every silhouette (lights do not move them)
    std::vector<std::vector<std::uint8_t>> specular; // compared ∧ highlight, per light count
    qint64 previousTriangles = -1;                   // of the last detail level measured
    // With two objects or more: per pixel the object the reference sees
    // there (-1 none), for the per-object rows; empty otherwise.
    std::vector<int> objectIds;
    RgbImage lastImage; // the frame measure() compared last
};

namespace {

std::vector<std::uint8_t> highlightMask(const ReferenceImage &reference,
                                        const std::vector<std::uint8_t> &compared, double threshold)
{
    std::vector<std::uint8_t> mask(reference.color.size(), 0);
    if (reference.specular.size() != mask.size())
        return mask;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        const glm::dvec3 &s = reference.specular[i];
        mask[i] = compared[i] && reference.coverage[i] && std::max({s.r, s.g, s.b}) >= threshold;
    }
    return mask;
}

void setTiming(BenchRow &row, const FrameTiming &timing)
{
    row.frameMs = timing.wallMedianMs;
    row.frameMsP90 = timing.wallP90Ms;
    row.cpuSubmitMs = timing.cpuSubmitMedianMs;
    row.gpuMs = timing.gpuMedianMs;
    row.frames = timing.frames;
}

void setError(BenchRow &row, const BandComparison &comparison)
{
    row.psnr = comparison.error.psnr;
    row.rmse = comparison.error.rmse;
    row.maxError = comparison.error.maxError;
    row.pixelsCompared = comparison.error.pixelsCompared;
    row.coverageErrors = comparison.coverageErrors;
}

Scene withLights(Scene scene, int count)
{
    scene.lights = lightsForCount(scene, count);
    return scene;
}

// Every object at one fixed detail and, with it, the method the row is
// labelled with: an object's own "shading" or "detail": "auto" would draw
// something else than the row says.
Scene withDetail(Scene scene, double detail)
{
    for (SceneObject &object : scene.objects) {
        object.detail = detail;
        object.autoDetail = false;
        object.shading.reset();
    }
    return scene;
}

} // namespace

std::vector<int> benchLightCounts(const BenchOptions &options, int sceneLights)
{
    std::set<int> counts;
    for (int c : options.lightCounts)
        counts.insert(std::clamp(c, 1, kMaxLights));
    if (options.sceneLights)
        counts.insert(std::clamp(sceneLights, 0, kMaxLights));
    return {counts.begin(), counts.end()};
}

int benchConfigurationCount(const BenchOptions &options, const std::vector<int> &sceneLightCounts)
{
    int total = 0;
    for (int own : sceneLightCounts)
        total += int(options.details.size() * options.methods.size()
                     * benchLightCounts(options, own).size());
    return total;
}

BenchEngine::BenchEngine() = default;
BenchEngine::~BenchEngine() = default;

Result<> BenchEngine::initialize()
{
    m_offscreen = std::make_unique<OffscreenRenderer>();
    Result<> created = m_offscreen->create();
    if (!created)
        m_offscreen.reset();
    return created;
}

QString BenchEngine::glRendererName() const
{
    return m_offscreen ? m_offscreen->glRendererName() : QString();
}

Result<> BenchEngine::run(const BenchOptions &options, std::vector<BenchRow> *rows,
                          const BenchProgressFn &progress)
{
    if (!m_offscreen)
        return fail(BenchEngineWords::tr(
            "the bench has no OpenGL context (initialize() failed or was not called)"));
    // Load every scene first: a bad file fails the run before any measuring,
    // and the progress total is known from the start.
    std::vector<SceneRun> runs(std::size_t(options.scenes.size()));
    std::vector<int> own;
    for (qsizetype i = 0; i < options.scenes.size(); ++i) {
        const QString &path = options.scenes[i];
        const SceneLoadResult loaded = loadSceneFile(path);
        if (!loaded.ok())
            return fail(QStringLiteral("%1: %2").arg(path, loaded.error));
        SceneRun &state = runs[std::size_t(i)];
        state.name = QFileInfo(path).completeBaseName();
        state.scene = *loaded.scene;
        state.ownLights = state.scene.enabledLightCount();
        state.lightCounts = benchLightCounts(options, state.ownLights);
        own.push_back(state.ownLights);
    }
    m_objectFits.clear();
    m_done = 0;
    m_total = benchConfigurationCount(options, own);
    for (qsizetype i = 0; i < options.scenes.size(); ++i)
        if (Result<> done =
                runScene(options, options.scenes[i], runs[std::size_t(i)], rows, progress);
            !done)
            return done;
    return {};
}

Result<> BenchEngine::runScene(const BenchOptions &options, const QString &path, SceneRun &state,
                               std::vector<BenchRow> *rows, const BenchProgressFn &progress)
{
    auto report = [&](const QString &stage) {
        return !progress || progress(BenchProgress{m_done, m_total, stage, {}});
    };
    // The reference always sees the full-resolution meshes: it is the exact
    // answer every detail level is measured against.
    const Scene full = withDetail(state.scene, 1.0);
    if (!report(BenchEngineWords::tr("%1: loading meshes").arg(state.name)))
        return fail(QStringLiteral("cancelled"));
    SceneMeshes meshes = loadSceneMeshes(full);
    if (!meshes.ok())
        return fail(QStringLiteral("%1: %2").arg(path, meshes.error));
    for (const SceneObject &object : full.objects) {
        const bool analytic = isBuiltinMeshSpec(object.mesh);
        state.fullMeshes.push_back(analytic ? nullptr
                                            : meshes.entries.value(meshKey(full, object)).mesh);
    }
    for (int count : state.lightCounts) {
        if (!report(QStringLiteral("%1: reference, %2 light(s)").arg(state.name).arg(count)))
            return fail(QStringLiteral("cancelled"));
        auto reference =
            raycastSceneMeshes(withLights(full, count), state.fullMeshes, options.size.width(),
                               options.size.height(), ReferenceShading::Phong);
        if (!reference)
            return fail(BenchEngineWords::tr("%1: no reference: %2").arg(path, reference.error()));
        if (state.compared.empty()) {
            auto compared = awayFromSilhouettes(*reference, full, state.fullMeshes, options.bandPx);
            if (!compared)
                return fail(
                    BenchEngineWords::tr("%1: no silhouette mask: %2").arg(path, compared.error()));
            state.compared = std::move(*compared);
        }
        state.specular.push_back(
            highlightMask(*reference, state.compared, options.specularThreshold));
        state.references.push_back(std::move(*reference));
    }
    if (options.objectFitBudget && full.objects.size() > 1) {
        const Result<SceneHits> hits =
            castSceneHits(full, state.fullMeshes, options.size.width(), options.size.height());
        if (!hits)
            return fail(QStringLiteral("%1: %2").arg(path, hits.error()));
        for (const ReferenceHit &hit : hits->hits)
            state.objectIds.push_back(hit.object);
    }
    const std::size_t firstRow = rows->size();
    for (double detail : options.details)
        if (Result<> done = measureDetail(options, state, detail, rows, progress); !done)
            return done;
    if (options.objectFitBudget && !state.objectIds.empty())
        return checkObjectFit(options, state, *rows, firstRow);
    return {};
}

// One row per object of the frame measure() just compared: the object
// drawn alone for its time, its own pixels of that frame for its error.
void BenchEngine::measureObjects(const BenchOptions &options, SceneRun &state, std::size_t setup,
                                 std::vector<BenchRow> *rows)
{
    Renderer &renderer = m_offscreen->renderer();
    const BenchRow whole = rows->back();
    const ReferenceImage &reference = state.references[setup];
    for (std::size_t o = 0; o < state.scene.objects.size(); ++o) {
        std::vector<std::uint8_t> own = state.compared;
        for (std::size_t i = 0; i < own.size(); ++i)
            own[i] = own[i] && state.objectIds[i] == int(o);
        const BandComparison error = compareOutsideBand(
            state.lastImage, reference, state.scene.background, options.bandPx, &own);
        Renderer::Options alone = renderer.options();
        alone.onlyObject = int(o);
        renderer.setOptions(alone);
        const FrameTiming timing =
            m_offscreen->timeFrames(options.size, options.warmupFrames, options.frames);
        BenchRow row = whole;
        row.object =
            QStringLiteral("%1: %2").arg(o).arg(QFileInfo(state.scene.objects[o].mesh).fileName());
        row.triangles = renderer.trianglesDrawn();
        setTiming(row, timing);
        setError(row, error);
        row.specularPixels = 0;
        row.specularPsnr = row.specularRmse = 0;
        row.specularMaxError = 0;
        alone.onlyObject = -1;
        renderer.setOptions(alone);
        rows->push_back(row);
    }
}

// The per-object fit of the rows just measured, drawn whole once: the
// combination's real time and error.
Result<> BenchEngine::checkObjectFit(const BenchOptions &options, SceneRun &state,
                                     const std::vector<BenchRow> &rows, std::size_t firstRow)
{
    const auto own = std::find(state.lightCounts.begin(), state.lightCounts.end(), state.ownLights);
    if (own == state.lightCounts.end())
        return {};
    std::vector<BenchRow> sceneRows;
    for (std::size_t i = firstRow; i < rows.size(); ++i)
        if (rows[i].sceneLights)
            sceneRows.push_back(rows[i]);
    ObjectFitCheck check{state.name, fitObjects(sceneRows, *options.objectFitBudget), std::nullopt};
    // One choice per object, in object order (the rows come so), or nothing to draw.
    if (check.fit.fits && check.fit.choices.size() == state.scene.objects.size()) {
        Scene combined = withLights(state.scene, state.ownLights);
        for (std::size_t o = 0; o < combined.objects.size(); ++o) {
            const BenchRow &row = sceneRows[std::size_t(check.fit.choices[o].row)];
            combined.objects[o].shading = shadingFromName(row.method);
            combined.objects[o].detail = row.detail;
            combined.objects[o].autoDetail = false;
        }
        m_offscreen->makeCurrent();
        Renderer &renderer = m_offscreen->renderer();
        if (const Result<> set = renderer.setScene(combined); !set)
            return fail(
                BenchEngineWords::tr("%1, per-object fit: %2").arg(state.name, set.error()));
        if (const BuildReport built = renderer.loadShading(combined.shading); !built.ok)
            return fail(BenchEngineWords::tr("%1, per-object fit: %2")
                            .arg(state.name, built.errorSummary()));
        check.measured = measureFrame(options, state, std::size_t(own - state.lightCounts.begin()),
                                      combined, QStringLiteral("per-object"), 1.0);
    }
    m_objectFits.push_back(std::move(check));
    return {};
}

Result<> BenchEngine::measureDetail(const BenchOptions &options, SceneRun &state, double detail,
                                    std::vector<BenchRow> *rows, const BenchProgressFn &progress)
{
    const Scene scene = withDetail(state.scene, detail);
    SceneMeshes meshes = loadSceneMeshes(scene);
    qint64 triangles = 0;
    for (const SceneObject &object : scene.objects)
        triangles += meshes.entries.value(meshKey(scene, object)).stats.triangles;
    if (meshes.ok() && triangles == state.previousTriangles) {
        // Nothing coarser to be had (a box has no levels; a tessellation at
        // its minimum): the same meshes again would only repeat rows.
        m_done += int(options.methods.size() * state.lightCounts.size());
        const QString stage =
            BenchEngineWords::tr(
                "%1: detail %2 draws the same %3 triangles as the level before; skipped")
                .arg(state.name, detailPercent(detail))
                .arg(triangles);
        if (progress && !progress(BenchProgress{m_done, m_total, stage, {}}))
            return fail(QStringLiteral("cancelled"));
        return {};
    }
    state.previousTriangles = triangles;
    Renderer &renderer = m_offscreen->renderer();
    m_offscreen->makeCurrent();
    if (const Result<> set = renderer.setScene(scene, std::move(meshes)); !set)
        return fail(BenchEngineWords::tr("%1 at detail %2: %3")
                        .arg(state.name, detailPercent(detail), set.error()));
    for (ShadingMethod method : options.methods) {
        const BuildReport built = renderer.loadShading(method);
        if (!built.ok)
            return fail(BenchEngineWords::tr("%1: the shipped %2 shaders did not build: %3")
                            .arg(state.name, shadingName(method), built.errorSummary()));
        for (std::size_t s = 0; s < state.lightCounts.size(); ++s) {
            const std::size_t first = rows->size();
            rows->push_back(measure(options, state, s, method, detail));
            if (!state.objectIds.empty() && rows->back().sceneLights)
                measureObjects(options, state, s, rows);
            ++m_done;
            const QString stage = QStringLiteral("%1: %2, detail %3, %4 light(s)")
                                      .arg(state.name, shadingName(method), detailPercent(detail))
                                      .arg(state.lightCounts[s]);
            const std::span<const BenchRow> measured(rows->data() + first, rows->size() - first);
            if (progress && !progress(BenchProgress{m_done, m_total, stage, measured}))
                return fail(QStringLiteral("cancelled"));
        }
    }
    return {};
}

BenchRow BenchEngine::measure(const BenchOptions &options, SceneRun &state, std::size_t setup,
                              ShadingMethod method, double detail)
{
    Scene scene = withLights(withDetail(state.scene, detail), state.lightCounts[setup]);
    scene.shading = method;
    m_offscreen->renderer().updateSceneParameters(scene);
    return measureFrame(options, state, setup, scene, shadingName(method), detail);
}

BenchRow BenchEngine::measureFrame(const BenchOptions &options, SceneRun &state, std::size_t setup,
                                   const Scene &scene, const QString &method, double detail)
{
    Renderer &renderer = m_offscreen->renderer();
    const int count = state.lightCounts[setup];

    const FrameTiming timing =
        m_offscreen->timeFrames(options.size, options.warmupFrames, options.frames);
    const QImage image = m_offscreen->renderImage(options.size);
    const ReferenceImage &reference = state.references[setup];
    const RgbImage pixels = toRgbImage(image);
    state.lastImage = pixels;
    const BandComparison all =
        compareOutsideBand(pixels, reference, scene.background, options.bandPx, &state.compared);
    const BandComparison highlight = compareOutsideBand(pixels, reference, scene.background,
                                                        options.bandPx, &state.specular[setup]);

    BenchRow row;
    row.scene = state.name;
    row.method = method;
    row.detail = detail;
    row.triangles = renderer.trianglesDrawn();
    row.lights = count;
    row.sceneLights = count == state.ownLights;
    setTiming(row, timing);
    setError(row, all);
    row.specularPsnr = highlight.error.psnr;
    row.specularRmse = highlight.error.rmse;
    row.specularMaxError = highlight.error.maxError;
    row.specularPixels = highlight.error.pixelsCompared;

    if (!options.imageDir.isEmpty() && row.sceneLights) {
        const QString file = QStringLiteral("%1/%2_%3_detail%4.png")
                                 .arg(options.imageDir, state.name, row.method)
                                 .arg(qRound(detail * 10000), 5, 10, QLatin1Char('0'));
        QDir().mkpath(options.imageDir);
        benchTriptych(image, reference, scene.background, options.bandPx, &state.compared,
                      QStringLiteral("%1 · %2 · detail %3 · %4 triangles · %5 ms · max %6/255")
                          .arg(state.name, row.method, detailPercent(detail))
                          .arg(row.triangles)
                          .arg(row.frameMs, 0, 'f', 2)
                          .arg(row.maxError))
            .save(file);
    }
    return row;
}

} // namespace phonglab
