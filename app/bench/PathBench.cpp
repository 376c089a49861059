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

} // namespace

Result<PathRun> PathBench::run(const QString &scenePath, const QString &pathSpec,
                               const PathOptions &options, const PathProgressFn &progress)
{
    if (!m_auto || !m_full)
        return fail(PathBenchWords::tr("the path bench has no OpenGL context"));
    const SceneLoadResult loaded = loadSceneFile(scenePath);
    if (!loaded.ok())
        return fail(QStringLiteral("%1: %2").arg(scenePath, loaded.error));
    Scene full = *loaded.scene;
    for (SceneObject &object : full.objects) {
        object.detail = 1.0;
        object.autoDetail = false;
    }
    Scene automatic = full;
    for (SceneObject &object : automatic.objects)
        object.autoDetail = true;

    SceneMeshes fullMeshes = loadSceneMeshes(full);
    if (!fullMeshes.ok())
        return fail(QStringLiteral("%1: %2").arg(scenePath, fullMeshes.error));
    // The reference ray-casts the analytic surface of a builtin and the
    // full mesh of anything else.
    std::vector<std::shared_ptr<const MeshData>> referenceMeshes;
    for (const SceneObject &object : full.objects)
        referenceMeshes.push_back(isBuiltinMeshSpec(object.mesh)
                                      ? nullptr
                                      : fullMeshes.entries.value(meshKey(full, object)).mesh);

    Result<CameraPath> path = pathSpec == QLatin1String("orbit")
        ? orbitPath(full.camera, options.pathFrames)
        : pathSpec == QLatin1String("dolly")
        ? dollyPath(full.camera, sceneBounds(full, fullMeshes), options.pathFrames)
        : loadCameraPath(pathSpec, full.camera);
    if (!path)
        return fail(path.error());

    SceneMeshes autoMeshes = loadSceneMeshes(automatic);
    if (!autoMeshes.ok())
        return fail(QStringLiteral("%1: %2").arg(scenePath, autoMeshes.error));
    Renderer &fast = m_auto->renderer();
    Renderer &exact = m_full->renderer();
    m_auto->makeCurrent();
    if (Result<> set = fast.setScene(automatic, std::move(autoMeshes)); !set)
        return fail(set.error());
    if (const BuildReport built = fast.loadShading(automatic.shading); !built.ok)
        return fail(built.errorSummary());
    Renderer::Options fastOptions = fast.options();
    fastOptions.lightAllowance = options.budget.reductionAllowance();
    fastOptions.detailShadingAllowance = options.budget.reductionAllowance();
    fastOptions.detailPixels = options.detailPixels;
    fast.setOptions(fastOptions);
    m_full->makeCurrent();
    if (Result<> set = exact.setScene(full, std::move(fullMeshes)); !set)
        return fail(set.error());
    if (const BuildReport built = exact.loadShading(full.shading); !built.ok)
        return fail(built.errorSummary());

    PathRun run;
    run.scene = QFileInfo(scenePath).completeBaseName();
    run.path = path->name;
    const int total = int(path->cameras.size());
    for (int i = 0; i < total; ++i) {
        const Camera &camera = path->cameras[std::size_t(i)];
        const Scene exactScene = withCamera(full, camera);
        Result<ReferenceImage> reference =
            raycastSceneMeshes(exactScene, referenceMeshes, options.size.width(),
                               options.size.height(), ReferenceShading::Phong);
        if (!reference)
            return fail(PathBenchWords::tr("%1, frame %2: no reference: %3")
                            .arg(run.scene)
                            .arg(i)
                            .arg(reference.error()));
        const Result<std::vector<std::uint8_t>> compared =
            awayFromSilhouettes(*reference, exactScene, referenceMeshes, options.bandPx);
        if (!compared)
            return fail(compared.error());

        PathFrame frame;
        frame.index = i;
        frame.eye = camera.eye;
        frame.distance = glm::length(camera.eye - camera.target);

        m_full->makeCurrent();
        exact.updateSceneParameters(exactScene);
        frame.fullFrameMs =
            m_full->timeFrames(options.size, options.warmupFrames, options.frames).wallMedianMs;
        frame.fullTriangles = exact.trianglesDrawn();
        const BandComparison fullError =
            compareOutsideBand(toRgbImage(m_full->renderImage(options.size)), *reference,
                               full.background, options.bandPx, &*compared);
        frame.fullMaxError = fullError.error.maxError;
        frame.fullOverBudget = !options.budget.accepts(frame.fullMaxError, fullError.error.psnr);

        m_auto->makeCurrent();
        fast.updateSceneParameters(withCamera(automatic, camera));
        frame.frameMs =
            m_auto->timeFrames(options.size, options.warmupFrames, options.frames).wallMedianMs;
        const QImage image = m_auto->renderImage(options.size);
        frame.triangles = fast.trianglesDrawn();
        frame.lightsLeftOut = fast.lightsLeftOut();
        frame.levels = levelsText(fast.objectDraws());
        if (!fast.drawError().isEmpty())
            return fail(fast.drawError());

        const BandComparison error = compareOutsideBand(
            toRgbImage(image), *reference, full.background, options.bandPx, &*compared);
        frame.maxError = error.error.maxError;
        frame.psnr = error.error.psnr;
        frame.rmse = error.error.rmse;
        frame.pixelsCompared = error.error.pixelsCompared;
        frame.overBudget = !options.budget.accepts(frame.maxError, frame.psnr);
        if (!options.imageDir.isEmpty()) {
            QDir().mkpath(options.imageDir);
            benchTriptych(image, *reference, full.background, options.bandPx, &*compared,
                          QStringLiteral("%1 · %2 frame %3 · levels %4 · %5 triangles · max %6/255")
                              .arg(run.scene, run.path)
                              .arg(i)
                              .arg(frame.levels)
                              .arg(frame.triangles)
                              .arg(frame.maxError))
                .save(QStringLiteral("%1/path_%2_%3_%4.png")
                          .arg(options.imageDir, run.scene, run.path)
                          .arg(i, 3, 10, QLatin1Char('0')));
        }
        run.frames.push_back(frame);
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
