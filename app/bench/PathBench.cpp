#include "PathBench.h"

#include "BenchPictures.h"
#include "BenchResult.h"
#include "core/reference/ImageMetrics.h"
#include "core/reference/MeshRaycaster.h"
#include "core/reference/ReferenceEdges.h"
#include "core/scene/SceneJson.h"
#include "mesh/import/BuiltinMeshes.h"
#include "mesh/loading/SceneMeshes.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/QtImages.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <cmath>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct PathBenchWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PathBench)
};

int PathRun::overBudget() const
{
    return int(std::count_if(frames.begin(), frames.end(),
                             [](const PathFrame &f) { return f.overBudget; }));
}

namespace {

template <typename T> T sumOver(const std::vector<PathFrame> &frames, T PathFrame::*field)
{
    T sum{};
    for (const PathFrame &f : frames)
        sum += f.*field;
    return sum;
}

} // namespace

int PathRun::fullOverBudget() const
{
    return int(std::count_if(frames.begin(), frames.end(),
                             [](const PathFrame &f) { return f.fullOverBudget; }));
}

qint64 PathRun::triangles() const
{
    return sumOver(frames, &PathFrame::triangles);
}

qint64 PathRun::fullTriangles() const
{
    return sumOver(frames, &PathFrame::fullTriangles);
}

double PathRun::frameMs() const
{
    return sumOver(frames, &PathFrame::frameMs);
}

double PathRun::fullFrameMs() const
{
    return sumOver(frames, &PathFrame::fullFrameMs);
}

PathBench::PathBench() = default;
PathBench::~PathBench() = default;

Result<> PathBench::initialize()
{
    m_auto = std::make_unique<OffscreenRenderer>();
    m_full = std::make_unique<OffscreenRenderer>();
    if (Result<> made = m_auto->create(); !made)
        return made;
    return m_full->create();
}

QString PathBench::glRendererName() const
{
    return m_auto ? m_auto->glRendererName() : QString();
}

namespace {

Scene withCamera(Scene scene, const Camera &camera)
{
    scene.camera = camera;
    return scene;
}

// Everything the scene shows, for the dolly to start just outside of.
BoundingSphere sceneBounds(const Scene &scene, const SceneMeshes &meshes)
{
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const SceneObject &object : scene.objects) {
        const MeshStats &stats = meshes.entries.value(meshKey(scene, object)).stats;
        const BoundingSphere s = boundingSphere(
            glm::dvec3(stats.boundsMin), glm::dvec3(stats.boundsMax), object.transform.matrix());
        lo = glm::min(lo, s.center - glm::dvec3(s.radius));
        hi = glm::max(hi, s.center + glm::dvec3(s.radius));
    }
    return {0.5 * (lo + hi), 0.5 * glm::length(hi - lo)};
}

QString levelsText(const std::vector<Renderer::ObjectDraw> &draws)
{
    QStringList parts;
    for (const Renderer::ObjectDraw &d : draws)
        parts << QStringLiteral("%1/%2").arg(d.level).arg(d.levels);
    return parts.join(QLatin1Char(' '));
}

// Both versions of the scene a path is drawn with: every object at full
// detail, and the same objects with their detail left to the renderer.
struct PathScenes {
    Scene full;
    Scene automatic;
};

PathScenes fullAndAutomatic(const Scene &loaded)
{
    PathScenes scenes{loaded, {}};
    for (SceneObject &object : scenes.full.objects) {
        object.detail = 1.0;
        object.autoDetail = false;
    }
    scenes.automatic = scenes.full;
    for (SceneObject &object : scenes.automatic.objects)
        object.autoDetail = true;
    return scenes;
}

// The reference ray-casts the analytic surface of a builtin and the
// full mesh of anything else.
std::vector<std::shared_ptr<const MeshData>> referenceMeshesOf(const Scene &full,
                                                               const SceneMeshes &fullMeshes)
{
    std::vector<std::shared_ptr<const MeshData>> referenceMeshes;
    for (const SceneObject &object : full.objects)
        referenceMeshes.push_back(isBuiltinMeshSpec(object.mesh)
                                      ? nullptr
                                      : fullMeshes.entries.value(meshKey(full, object)).mesh);
    return referenceMeshes;
}

Result<CameraPath> cameraPathFor(const QString &pathSpec, const Scene &full,
                                 const SceneMeshes &fullMeshes, int pathFrames)
{
    return pathSpec == QLatin1String("orbit") ? orbitPath(full.camera, pathFrames)
        : pathSpec == QLatin1String("dolly")
        ? dollyPath(full.camera, sceneBounds(full, fullMeshes), pathFrames)
        : loadCameraPath(pathSpec, full.camera);
}

Result<> loadIntoRenderer(OffscreenRenderer &target, const Scene &scene, SceneMeshes meshes)
{
    Renderer &renderer = target.renderer();
    target.makeCurrent();
    if (Result<> set = renderer.setScene(scene, std::move(meshes)); !set)
        return fail(set.error());
    if (const BuildReport built = renderer.loadShading(scene.shading); !built.ok)
        return fail(built.errorSummary());
    return {};
}

// The automatic renderer may leave out lights and shading detail as far as
// the error budget allows; the full one keeps its defaults.
Result<> prepareRenderers(OffscreenRenderer &fast, OffscreenRenderer &exact,
                          const QString &scenePath, const PathScenes &scenes,
                          SceneMeshes fullMeshes, const PathOptions &options)
{
    SceneMeshes autoMeshes = loadSceneMeshes(scenes.automatic);
    if (!autoMeshes.ok())
        return fail(QStringLiteral("%1: %2").arg(scenePath, autoMeshes.error));
    if (Result<> loaded = loadIntoRenderer(fast, scenes.automatic, std::move(autoMeshes)); !loaded)
        return loaded;
    Renderer::Options fastOptions = fast.renderer().options();
    fastOptions.lightAllowance = options.budget.reductionAllowance();
    fastOptions.detailShadingAllowance = options.budget.reductionAllowance();
    fastOptions.detailPixels = options.detailPixels;
    fast.renderer().setOptions(fastOptions);
    return loadIntoRenderer(exact, scenes.full, std::move(fullMeshes));
}

// What every frame of one path run shares.
struct PathContext {
    OffscreenRenderer &fast;  // auto detail, lights left out
    OffscreenRenderer &exact; // full detail, every light
    const PathScenes &scenes;
    const std::vector<std::shared_ptr<const MeshData>> &referenceMeshes;
    const PathOptions &options;
};

// The exact answer for one camera, and the pixels far enough from a
// silhouette to be compared with it.
struct FrameReference {
    ReferenceImage image;
    std::vector<std::uint8_t> compared;
};

Result<FrameReference> frameReference(const PathContext &context, const Scene &exactScene,
                                      const QString &sceneName, int index)
{
    const PathOptions &options = context.options;
    Result<ReferenceImage> reference =
        raycastSceneMeshes(exactScene, context.referenceMeshes, options.size.width(),
                           options.size.height(), ReferenceShading::Phong);
    if (!reference)
        return fail(PathBenchWords::tr("%1, frame %2: no reference: %3")
                        .arg(sceneName)
                        .arg(index)
                        .arg(reference.error()));
    Result<std::vector<std::uint8_t>> compared =
        awayFromSilhouettes(*reference, exactScene, context.referenceMeshes, options.bandPx);
    if (!compared)
        return fail(compared.error());
    return FrameReference{std::move(*reference), std::move(*compared)};
}

void measureFullFrame(const PathContext &context, const Scene &exactScene,
                      const FrameReference &reference, PathFrame &frame)
{
    const PathOptions &options = context.options;
    Renderer &exact = context.exact.renderer();
    context.exact.makeCurrent();
    exact.updateSceneParameters(exactScene);
    frame.fullFrameMs =
        context.exact.timeFrames(options.size, options.warmupFrames, options.frames).wallMedianMs;
    frame.fullTriangles = exact.trianglesDrawn();
    const BandComparison fullError =
        compareOutsideBand(toRgbImage(context.exact.renderImage(options.size)), reference.image,
                           context.scenes.full.background, options.bandPx, &reference.compared);
    frame.fullMaxError = fullError.error.maxError;
    frame.fullOverBudget = !options.budget.accepts(frame.fullMaxError, fullError.error.psnr);
}

// The frame as the automatic renderer draws it, for the picture of the frame.
Result<QImage> measureAutoFrame(const PathContext &context, const Camera &camera,
                                const FrameReference &reference, PathFrame &frame)
{
    const PathOptions &options = context.options;
    Renderer &fast = context.fast.renderer();
    context.fast.makeCurrent();
    fast.updateSceneParameters(withCamera(context.scenes.automatic, camera));
    frame.frameMs =
        context.fast.timeFrames(options.size, options.warmupFrames, options.frames).wallMedianMs;
    QImage image = context.fast.renderImage(options.size);
    frame.triangles = fast.trianglesDrawn();
    frame.lightsLeftOut = fast.lightsLeftOut();
    frame.levels = levelsText(fast.objectDraws());
    if (!fast.drawError().isEmpty())
        return fail(fast.drawError());

    const BandComparison error =
        compareOutsideBand(toRgbImage(image), reference.image, context.scenes.full.background,
                           options.bandPx, &reference.compared);
    frame.maxError = error.error.maxError;
    frame.psnr = error.error.psnr;
    frame.rmse = error.error.rmse;
    frame.pixelsCompared = error.error.pixelsCompared;
    frame.overBudget = !options.budget.accepts(frame.maxError, frame.psnr);
    return image;
}

void saveFramePicture(const PathContext &context, const PathRun &run, const PathFrame &frame,
                      const QImage &image, const FrameReference &reference)
{
    const PathOptions &options = context.options;
    QDir().mkpath(options.imageDir);
    benchTriptych(image, reference.image, context.scenes.full.background, options.bandPx,
                  &reference.compared,
                  QStringLiteral("%1 · %2 frame %3 · levels %4 · %5 triangles · max %6/255")
                      .arg(run.scene, run.path)
                      .arg(frame.index)
                      .arg(frame.levels)
                      .arg(frame.triangles)
                      .arg(frame.maxError))
        .save(QStringLiteral("%1/path_%2_%3_%4.png")
                  .arg(options.imageDir, run.scene, run.path)
                  .arg(frame.index, 3, 10, QLatin1Char('0')));
}

Result<PathFrame> measurePathFrame(const PathContext &context, const PathRun &run, int index,
                                   const Camera &camera)
{
    const Scene exactScene = withCamera(context.scenes.full, camera);
    const Result<FrameReference> reference = frameReference(context, exactScene, run.scene, index);
    if (!reference)
        return fail(reference.error());

    PathFrame frame;
    frame.index = index;
    frame.eye = camera.eye;
    frame.distance = glm::length(camera.eye - camera.target);
    measureFullFrame(context, exactScene, *reference, frame);
    const Result<QImage> image = measureAutoFrame(context, camera, *reference, frame);
    if (!image)
        return fail(image.error());
    if (!context.options.imageDir.isEmpty())
        saveFramePicture(context, run, frame, *image, *reference);
    return frame;
}

} // namespace

Result<PathRun> PathBench::run(const QString &scenePath, const QString &pathSpec,
                               const PathOptions &options, const PathProgressFn &progress)
{
    if (!m_auto || !m_full)
        return fail(PathBenchWords::tr("the path bench has no OpenGL context"));
    const SceneLoadResult loaded = loadSceneFile(scenePath);
    if (!loaded.ok())
        return fail(QStringLiteral("%1: %2").arg(scenePath, loaded.error));
    const PathScenes scenes = fullAndAutomatic(*loaded.scene);

    SceneMeshes fullMeshes = loadSceneMeshes(scenes.full);
    if (!fullMeshes.ok())
        return fail(QStringLiteral("%1: %2").arg(scenePath, fullMeshes.error));
    const std::vector<std::shared_ptr<const MeshData>> referenceMeshes =
        referenceMeshesOf(scenes.full, fullMeshes);
    Result<CameraPath> path = cameraPathFor(pathSpec, scenes.full, fullMeshes, options.pathFrames);
    if (!path)
        return fail(path.error());
    if (Result<> ready =
            prepareRenderers(*m_auto, *m_full, scenePath, scenes, std::move(fullMeshes), options);
        !ready)
        return fail(ready.error());

    PathRun run;
    run.scene = QFileInfo(scenePath).completeBaseName();
    run.path = path->name;
    const PathContext context{*m_auto, *m_full, scenes, referenceMeshes, options};
    const int total = int(path->cameras.size());
    for (int i = 0; i < total; ++i) {
        Result<PathFrame> frame = measurePathFrame(context, run, i, path->cameras[std::size_t(i)]);
        if (!frame)
            return fail(frame.error());
        run.frames.push_back(*frame);
        if (progress && !progress(i + 1, total, run.frames.back()))
            return fail(QStringLiteral("cancelled"));
    }
    return run;
}

QString pathRunsToCsv(const std::vector<PathRun> &runs)
{
    QString csv = QStringLiteral(
        "scene,path,frame,eye_x,eye_y,eye_z,distance,max_error,psnr,rmse,pixels_compared,"
        "over_budget,frame_ms,full_frame_ms,triangles,full_triangles,lights_left_out,levels,"
        "full_max_error,full_over_budget\n");
    const auto num = [](double v) { return QString::number(v, 'g', 17); };
    for (const PathRun &run : runs)
        for (const PathFrame &f : run.frames)
            csv += QStringList{csvField(run.scene),
                               csvField(run.path),
                               QString::number(f.index),
                               num(f.eye.x),
                               num(f.eye.y),
                               num(f.eye.z),
                               num(f.distance),
                               QString::number(f.maxError),
                               std::isinf(f.psnr) ? QStringLiteral("inf") : num(f.psnr),
                               num(f.rmse),
                               QString::number(f.pixelsCompared),
                               f.overBudget ? QStringLiteral("1") : QStringLiteral("0"),
                               num(f.frameMs),
                               num(f.fullFrameMs),
                               QString::number(f.triangles),
                               QString::number(f.fullTriangles),
                               QString::number(f.lightsLeftOut),
                               csvField(f.levels),
                               QString::number(f.fullMaxError),
                               f.fullOverBudget ? QStringLiteral("1") : QStringLiteral("0")}
                       .join(QLatin1Char(','))
                + QLatin1Char('\n');
    return csv;
}

} // namespace phonglab
