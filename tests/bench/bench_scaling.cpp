// How each cost grows (prints figures and fitted slopes; not a test):
//   - PhongLab's frame (OffscreenRenderer: render + glFinish, no MSAA)
//     against the triangle count, 10^4 ... 10^7 (the UV sphere, finer and
//     finer), at 800x600, and against the pixel count, 0.25 ... 8 megapixels;
//   - the exact reference image (raycastSceneMeshes, BVH build included)
//     against the same two.
// Slopes are least-squares fits of log(time) on log(size): 1 is linear.
//
//   build/tests/bench/bench_scaling [--max-triangles N] [--frames N]
// Runs without a display server (EGL) or under X.
#include "BenchHelpers.h"
#include "core/MeshRaycaster.h"
#include "headless/HeadlessPlatform.h"
#include "mesh/BuiltinMeshes.h"
#include "render/OffscreenRenderer.h"
#include "render/ShaderSource.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QGuiApplication>
#include <cmath>
#include <cstdio>

using namespace phonglab;

namespace {

// One name per tessellation: the renderer keeps a mesh it has by its key.
Scene sphereScene(const MeshData &mesh)
{
    return bench::litObjectScene(QStringLiteral("uv-sphere-%1.mesh").arg(mesh.triangleCount()));
}

// The UV sphere with about `triangles` triangles (slices = 2 stacks).
std::shared_ptr<const MeshData> sphereOf(double triangles)
{
    const int stacks = std::max(3, int(std::lround(std::sqrt(triangles / 4.0))));
    return std::make_shared<const MeshData>(makeUvSphere(2 * stacks, stacks));
}

SceneMeshes meshesOf(const Scene &scene, const std::shared_ptr<const MeshData> &mesh)
{
    SceneMeshes meshes;
    SceneMeshes::Entry entry;
    entry.mesh = mesh;
    entry.stats.triangles = qint64(mesh->triangleCount());
    entry.stats.vertices = qint64(mesh->positions.size());
    entry.stats.closed = true;
    entry.stats.boundsMin = glm::vec3(-1.0f); // the unit sphere: the fitted depth range needs it
    entry.stats.boundsMax = glm::vec3(1.0f);
    meshes.entries.insert(meshKey(scene, scene.objects.front()), entry);
    return meshes;
}

double referenceMs(const Scene &scene, const std::shared_ptr<const MeshData> &mesh, QSize size)
{
    QElapsedTimer timer;
    timer.start();
    const auto image = raycastSceneMeshes(scene, {mesh}, size.width(), size.height(),
                                          ReferenceShader(ReferenceShading::Phong));
    return image ? double(timer.nsecsElapsed()) / 1e6 : std::nan("");
}

// A frame that draws nothing, or another mesh, would time the wrong thing:
// the sphere must cover about a fifth of the image (its share at this
// camera) with all of its triangles, else say so.
bool drawsTheSphere(OffscreenRenderer &gl, const QSize &size, const MeshData &mesh)
{
    const QImage image = gl.renderImage(size);
    const QRgb background = image.pixel(0, 0);
    qint64 covered = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            covered += image.pixel(x, y) != background;
    const double share = double(covered) / (double(size.width()) * size.height());
    if (share < 0.1) {
        std::fprintf(stderr, "the sphere covers %.1f %% of the image: nothing to time\n",
                     100.0 * share);
        return false;
    }
    if (gl.renderer().trianglesDrawn() != qint64(mesh.triangleCount())) {
        std::fprintf(stderr, "drew %lld triangles, not the mesh's %zu\n",
                     (long long)gl.renderer().trianglesDrawn(), mesh.triangleCount());
        return false;
    }
    return true;
}

// Least-squares slope of log(y) on log(x), over the points from `first` on
// (the large end, where fixed costs no longer hide the growth).
double slope(const std::vector<double> &x, const std::vector<double> &y, std::size_t first = 0)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = double(x.size() - first);
    for (std::size_t i = first; i < x.size(); ++i) {
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace

int main(int argc, char **argv)
{
    chooseCommandPlatform();
    QGuiApplication app(argc, argv);
    QCommandLineParser parser;
    parser.addHelpOption();
    parser.addOption({QStringLiteral("max-triangles"),
                      QStringLiteral("Largest mesh (default 10000000)."), QStringLiteral("N"),
                      QStringLiteral("10000000")});
    parser.addOption({QStringLiteral("frames"),
                      QStringLiteral("Timed frames per point (default 10)."), QStringLiteral("N"),
                      QStringLiteral("10")});
    parser.process(app);
    const double maxTriangles = parser.value(QStringLiteral("max-triangles")).toDouble();
    const int frames = std::max(3, parser.value(QStringLiteral("frames")).toInt());

    OffscreenRenderer gl;
    if (const Result<> created = gl.create(); !created) {
        std::fprintf(stderr, "%s\n", qPrintable(created.error()));
        return 1;
    }
    const Result<StageSources> phong =
        readStageFiles(shippedShaderPath(ShadingMethod::Phong, ShaderStage::Vertex),
                       shippedShaderPath(ShadingMethod::Phong, ShaderStage::Fragment));
    if (!phong || !gl.renderer().setProgramSources(phong->vertex, phong->fragment).ok) {
        std::fprintf(stderr, "the shipped Phong program does not build\n");
        return 1;
    }
    std::printf("%s\n\n", qPrintable(gl.glRendererName()));

    std::printf("against triangles, 800x600:\n\n| triangles | frame p50 ms | ms per million "
                "triangles | reference ms |\n|---|---|---|---|\n");
    std::vector<double> counts, frameTimes, referenceTimes;
    const QSize fixedSize(800, 600);
    for (double t = 1e4; t <= maxTriangles * 1.01; t *= std::sqrt(10.0)) {
        const auto mesh = sphereOf(t);
        const Scene scene = sphereScene(*mesh);
        if (const Result<> set = gl.renderer().setScene(scene, meshesOf(scene, mesh)); !set) {
            std::fprintf(stderr, "%s\n", qPrintable(set.error()));
            return 1;
        }
        gl.renderer().updateSceneParameters(scene);
        if (!drawsTheSphere(gl, fixedSize, *mesh))
            return 1;
        const FrameTiming timing = gl.timeFrames(fixedSize, 2, frames);
        const double triangles = double(mesh->triangleCount());
        const double refMs = referenceMs(scene, mesh, fixedSize);
        std::printf("| %.0f | %.2f | %.2f | %.1f |\n", triangles, timing.wallMedianMs,
                    timing.wallMedianMs / (triangles / 1e6), refMs);
        std::fflush(stdout);
        counts.push_back(triangles);
        frameTimes.push_back(timing.wallMedianMs);
        referenceTimes.push_back(refMs);
    }
    if (counts.size() >= 2) { // a slope needs two sizes
        const std::size_t topT = counts.size() > 3 ? counts.size() - 3 : 0;
        std::printf("\nslope of log(time) on log(triangles): frame %.2f, reference %.2f; over the "
                    "largest three: frame %.2f, reference %.2f\n",
                    slope(counts, frameTimes), slope(counts, referenceTimes),
                    slope(counts, frameTimes, topT), slope(counts, referenceTimes, topT));
    }

    std::printf("\nagainst pixels, a %d-triangle sphere:\n\n| pixels | size | frame p50 ms | "
                "reference ms |\n|---|---|---|---|\n",
                int(sphereOf(2e5)->triangleCount()));
    const auto mesh = sphereOf(2e5);
    const Scene scene = sphereScene(*mesh);
    if (const Result<> set = gl.renderer().setScene(scene, meshesOf(scene, mesh)); !set)
        return 1;
    gl.renderer().updateSceneParameters(scene);
    std::vector<double> pixels, pixelFrames, pixelReferences;
    for (double megapixels : {0.25, 0.5, 1.0, 2.0, 4.0, 8.0}) {
        const int width = int(std::lround(std::sqrt(megapixels * 1e6 * 4.0 / 3.0)));
        const QSize size(width, width * 3 / 4);
        if (!drawsTheSphere(gl, size, *mesh))
            return 1;
        const FrameTiming timing = gl.timeFrames(size, 2, frames);
        const double refMs = referenceMs(scene, mesh, size);
        std::printf("| %.2f M | %dx%d | %.2f | %.1f |\n", megapixels, size.width(), size.height(),
                    timing.wallMedianMs, refMs);
        std::fflush(stdout);
        pixels.push_back(double(size.width()) * size.height());
        pixelFrames.push_back(timing.wallMedianMs);
        pixelReferences.push_back(refMs);
    }
    const std::size_t topP = pixels.size() - 3;
    std::printf("\nslope of log(time) on log(pixels): frame %.2f, reference %.2f; over the "
                "largest three: frame %.2f, reference %.2f\n",
                slope(pixels, pixelFrames), slope(pixels, pixelReferences),
                slope(pixels, pixelFrames, topP), slope(pixels, pixelReferences, topP));
    return 0;
}
