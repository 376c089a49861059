// How each cost grows (prints figures, ratios and fitted slopes; not a test):
//   - PhongLab's offscreen frame (OffscreenRenderer: render + glFinish, no
//     MSAA) beside the raw path (the same mesh through plain GL calls into
//     an FBO of the same format, RawGlOffscreenPath), against the triangle
//     count, 10^4 ... 10^7 (the UV sphere, finer and finer), at 800x600, and
//     against the pixel count, 0.25 ... 8 megapixels;
//   - the exact reference image (raycastSceneMeshes, BVH build included),
//     and its BVH build alone, against the same two.
// The two paths' frames are timed in turn, frame by frame, so that other work
// on the machine slows both alike; the reference keeps its fastest run.
// Slopes are least-squares fits of log(time) on log(size): 1 is linear.
//
//   build/tests/bench/bench_scaling [--max-triangles N] [--frames N] [--reference-runs N]
//                                   [--csv FILE]
// Runs without a display server (EGL) or under X. --csv writes the points
// for bench_charts.
#include "ChartCsv.h"
#include "LogLogFit.h"
#include "RawGlOffscreenPath.h"
#include "ScalingMeshes.h"
#include "core/reference/MeshBvh.h"
#include "core/reference/MeshRaycaster.h"
#include "headless/HeadlessPlatform.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/program/ShaderSource.h"

#include <QCommandLineParser>
#include <QDate>
#include <QElapsedTimer>
#include <QGuiApplication>
#include <QThread>
#include <cmath>
#include <cstdio>

using namespace phonglab;
using namespace phonglab::bench;

namespace {

struct Options {
    double maxTriangles = 1e7;
    int frames = 10;
    int referenceRuns = 2;
};

// The fastest of `runs` (the run least disturbed by other work on the
// machine), ms; NaN when `work` fails.
template <typename Work> double fastestMs(int runs, Work work)
{
    double best = INFINITY;
    for (int i = 0; i < runs; ++i) {
        QElapsedTimer timer;
        timer.start();
        if (!work())
            return std::nan("");
        best = std::min(best, double(timer.nsecsElapsed()) / 1e6);
    }
    return best;
}

double referenceMs(const Scene &scene, const std::shared_ptr<const MeshData> &mesh, QSize size,
                   int runs)
{
    return fastestMs(runs, [&] {
        return bool(raycastSceneMeshes(scene, {mesh}, size.width(), size.height(),
                                       ReferenceShader(ReferenceShading::Phong)));
    });
}

// The part of the reference that depends on triangles alone.
double bvhBuildMs(const MeshData &mesh, int runs)
{
    return fastestMs(runs, [&] { return MeshBvh(mesh).nodeCount() > 0; });
}

// A frame that draws nothing, or another mesh, would time the wrong thing:
// the sphere must cover about a fifth of the image (its share at this
// camera) with all of its triangles, and the raw path must cover the same
// pixels give or take its edges, else say so.
bool drawsTheSphere(OffscreenRenderer &gl, RawGlOffscreenPath &raw, const QSize &size,
                    const MeshData &mesh)
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
    // PhongLab fits near and far to the scene, the raw path keeps the
    // camera's: the silhouettes agree, the depth precision differs.
    const double rawShare = raw.coveredShare(size);
    if (std::abs(rawShare / share - 1.0) > 0.02) {
        std::fprintf(stderr, "the raw path covers %.2f %% of the image, PhongLab %.2f %%\n",
                     100.0 * rawShare, 100.0 * share);
        return false;
    }
    return true;
}

// Both paths' median frame at `size`, ms, frame by frame in turn after two
// warm-up frames each: other work on the machine then slows both alike.
std::pair<double, double> timeBoth(OffscreenRenderer &gl, RawGlOffscreenPath &raw,
                                   const QSize &size, int frames)
{
    gl.timeFrames(size, 2, 1);
    gl.makeCurrent();
    raw.timeFrames(size, 2, 1);
    std::vector<double> ours, floor;
    for (int i = 0; i < frames; ++i) {
        ours.push_back(gl.timeFrames(size, 0, 1).wallMedianMs);
        gl.makeCurrent();
        floor.push_back(raw.timeFrames(size, 0, 1));
    }
    return {percentile(ours, 0.5), percentile(floor, 0.5)};
}

// Both paths draw `mesh` from here on; false after saying why.
bool useMesh(OffscreenRenderer &gl, RawGlOffscreenPath &raw,
             const std::shared_ptr<const MeshData> &mesh)
{
    const Scene scene = sphereScene(*mesh);
    if (const Result<> set = gl.renderer().setScene(scene, meshesOf(scene, mesh)); !set) {
        std::fprintf(stderr, "%s\n", qPrintable(set.error()));
        return false;
    }
    gl.renderer().updateSceneParameters(scene);
    gl.makeCurrent();
    raw.setMesh(*mesh, scene);
    return true;
}

struct Series {
    std::vector<double> x, phonglab, raw, reference, bvh;
};

void printSlopes(const char *against, const Series &s)
{
    if (s.x.size() < 2) // a slope needs two sizes
        return;
    const std::size_t top = largestThree(s.x);
    std::printf("\nslope of log(time) on log(%s), all points / largest three: PhongLab %.2f / "
                "%.2f, raw GL %.2f / %.2f, reference %.2f / %.2f",
                against, logLogSlope(s.x, s.phonglab), logLogSlope(s.x, s.phonglab, top),
                logLogSlope(s.x, s.raw), logLogSlope(s.x, s.raw, top),
                logLogSlope(s.x, s.reference), logLogSlope(s.x, s.reference, top));
    if (!s.bvh.empty())
        std::printf(", BVH build %.2f / %.2f", logLogSlope(s.x, s.bvh),
                    logLogSlope(s.x, s.bvh, top));
    std::printf("\n");
}

bool sweepTriangles(OffscreenRenderer &gl, RawGlOffscreenPath &raw, const Options &o, ChartCsv &csv)
{
    std::printf("against triangles, 800x600:\n\n| triangles | PhongLab ms | raw GL ms | ratio | "
                "PhongLab ms per million triangles | reference ms | BVH build ms |\n"
                "|---|---|---|---|---|---|---|\n");
    Series s;
    const QSize size(800, 600);
    for (double t = 1e4; t <= o.maxTriangles * 1.01; t *= std::sqrt(10.0)) {
        const auto mesh = sphereOf(t);
        if (!useMesh(gl, raw, mesh) || !drawsTheSphere(gl, raw, size, *mesh))
            return false;
        const auto [ours, floor] = timeBoth(gl, raw, size, o.frames);
        const double triangles = double(mesh->triangleCount());
        const double refMs = referenceMs(sphereScene(*mesh), mesh, size, o.referenceRuns);
        const double bvhMs = bvhBuildMs(*mesh, o.referenceRuns);
        std::printf("| %.0f | %.2f | %.2f | %.2fx | %.2f | %.1f | %.1f |\n", triangles, ours, floor,
                    ours / floor, ours / (triangles / 1e6), refMs, bvhMs);
        std::fflush(stdout);
        s.x.push_back(triangles);
        s.phonglab.push_back(ours);
        s.raw.push_back(floor);
        s.reference.push_back(refMs);
        s.bvh.push_back(bvhMs);
        csv.add(QStringLiteral("frame-vs-triangles"), QStringLiteral("PhongLab"), triangles, ours);
        csv.add(QStringLiteral("frame-vs-triangles"), QStringLiteral("raw GL"), triangles, floor);
        csv.add(QStringLiteral("reference-vs-triangles"),
                QStringLiteral("reference (BVH build + casting)"), triangles, refMs);
        csv.add(QStringLiteral("reference-vs-triangles"), QStringLiteral("BVH build alone"),
                triangles, bvhMs);
    }
    printSlopes("triangles", s);
    return true;
}

bool sweepPixels(OffscreenRenderer &gl, RawGlOffscreenPath &raw, const Options &o, ChartCsv &csv)
{
    const auto mesh = sphereOf(2e5);
    std::printf("\nagainst pixels, a %zu-triangle sphere:\n\n| pixels | size | PhongLab ms | "
                "raw GL ms | ratio | reference ms |\n|---|---|---|---|---|---|\n",
                mesh->triangleCount());
    if (!useMesh(gl, raw, mesh))
        return false;
    Series s;
    for (double megapixels : {0.25, 0.5, 1.0, 2.0, 4.0, 8.0}) {
        const int width = int(std::lround(std::sqrt(megapixels * 1e6 * 4.0 / 3.0)));
        const QSize size(width, width * 3 / 4);
        if (!drawsTheSphere(gl, raw, size, *mesh))
            return false;
        const auto [ours, floor] = timeBoth(gl, raw, size, o.frames);
        const double refMs = referenceMs(sphereScene(*mesh), mesh, size, o.referenceRuns);
        std::printf("| %.2f M | %dx%d | %.2f | %.2f | %.2fx | %.1f |\n", megapixels, size.width(),
                    size.height(), ours, floor, ours / floor, refMs);
        std::fflush(stdout);
        const double pixels = double(size.width()) * size.height();
        s.x.push_back(pixels);
        s.phonglab.push_back(ours);
        s.raw.push_back(floor);
        s.reference.push_back(refMs);
        csv.add(QStringLiteral("frame-vs-pixels"), QStringLiteral("PhongLab"), pixels / 1e6, ours);
        csv.add(QStringLiteral("frame-vs-pixels"), QStringLiteral("raw GL"), pixels / 1e6, floor);
        csv.add(QStringLiteral("reference-vs-pixels"), QStringLiteral("reference"), pixels / 1e6,
                refMs);
    }
    printSlopes("pixels", s);
    return true;
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
                      QStringLiteral("Timed frames per point and path (default 10)."),
                      QStringLiteral("N"), QStringLiteral("10")});
    parser.addOption({QStringLiteral("reference-runs"),
                      QStringLiteral("Reference images per point, the fastest kept (default 2)."),
                      QStringLiteral("N"), QStringLiteral("2")});
    parser.addOption({QStringLiteral("csv"), QStringLiteral("Write the points for bench_charts."),
                      QStringLiteral("FILE")});
    parser.process(app);
    Options o;
    o.maxTriangles = parser.value(QStringLiteral("max-triangles")).toDouble();
    o.frames = std::max(3, parser.value(QStringLiteral("frames")).toInt());
    o.referenceRuns = std::max(1, parser.value(QStringLiteral("reference-runs")).toInt());

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
    gl.makeCurrent();
    RawGlOffscreenPath raw; // destroyed before `gl`, while its context still exists
    if (!raw.create())
        return 1;
    const QString machine = QStringLiteral("%1, %2 cores, frames: median of %3 in turn with the "
                                           "other path, reference: fastest of %4, %5")
                                .arg(gl.glRendererName())
                                .arg(QThread::idealThreadCount())
                                .arg(o.frames)
                                .arg(o.referenceRuns)
                                .arg(QDate::currentDate().toString(Qt::ISODate));
    std::printf("%s\n\n", qPrintable(machine));
    ChartCsv csv(parser.value(QStringLiteral("csv")));
    csv.note(machine);
    if (!sweepTriangles(gl, raw, o, csv) || !sweepPixels(gl, raw, o, csv))
        return 1;
    gl.makeCurrent();
    return csv.save() ? 0 : 1;
}
