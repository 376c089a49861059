// How import time grows with the file (prints figures, ratios and fitted
// slopes; not a test): OBJ files of the UV sphere with normals, 10^4 ...
// about 3 x 10^6 triangles, written to a temporary folder; each opened by
// PhongLab (loadMesh's first open: a fresh, empty cache folder, the file
// parsed in the import child, its answer read back) and by tinyobjloader,
// each open in a fresh process (fork), the two interleaved run by run.
// Prints MB, ms, the ratio, MB/s and the peak memory, then the slope of
// log(time) on log(size).
//
//   build/tests/bench/bench_import_scaling [--max-triangles N] [--runs N] [--csv FILE]
#include "ChartCsv.h"
#include "LogLogFit.h"
#include "ScalingMeshes.h"
#include "mesh/loading/MeshLoader.h"

#include "ChildMeasure.h"
#include "TinyObjLoad.h"

#include <tiny_obj_loader.h>

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QThread>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace phonglab;
using namespace phonglab::bench;

namespace {

using Clock = std::chrono::steady_clock;

using Sample = ChildSample;

long long phonglabFirstOpen(const std::string &path, const QString &cacheDir)
{
    QDir(cacheDir).removeRecursively(); // nothing cached: the file is parsed
    const MeshLoadResult r = loadMesh(QString::fromStdString(path));
    return r.ok() ? r.stats.triangles : -1;
}

// `mesh` as OBJ: positions, normals, faces "f a//a b//b c//c", without the
// triangles that meet at the poles in a point (PhongLab's importer drops
// zero-area triangles; tinyobjloader keeps them), so that both read the
// same triangles. The triangles written; -1 when the file cannot be.
long long writeObj(const MeshData &mesh, const QString &path)
{
    std::FILE *out = std::fopen(qPrintable(path), "wb");
    if (!out)
        return -1;
    const auto vec = [&](const char *tag, const glm::vec3 &v) {
        std::fprintf(out, "%s %.7g %.7g %.7g\n", tag, double(v.x), double(v.y), double(v.z));
    };
    for (const glm::vec3 &p : mesh.positions)
        vec("v", p);
    for (const glm::vec3 &n : mesh.normals)
        vec("vn", n);
    long long written = 0;
    const auto &p = mesh.positions;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const unsigned a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        if (p[a] == p[b] || p[b] == p[c] || p[c] == p[a])
            continue;
        std::fprintf(out, "f %u//%u %u//%u %u//%u\n", a + 1, a + 1, b + 1, b + 1, c + 1, c + 1);
        ++written;
    }
    return std::fclose(out) == 0 ? written : -1;
}

Sample medianOf(std::vector<Sample> samples)
{
    std::sort(samples.begin(), samples.end(),
              [](const Sample &a, const Sample &b) { return a.ms < b.ms; });
    return samples[samples.size() / 2];
}

} // namespace

int main(int argc, char **argv)
{
    double maxTriangles = 3.2e6;
    int runs = 3;
    QString csvPath;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--max-triangles") == 0 && i + 1 < argc)
            maxTriangles = std::atof(argv[++i]);
        else if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else if (std::strcmp(argv[i], "--csv") == 0 && i + 1 < argc)
            csvPath = QString::fromLocal8Bit(argv[++i]);
        else {
            std::fprintf(stderr,
                         "usage: bench_import_scaling [--max-triangles N] [--runs N] "
                         "[--csv FILE]\n");
            return 2;
        }
    }
    QTemporaryDir files, cache;
    qputenv("PHONGLAB_CACHE_DIR", cache.path().toUtf8());
    const QString machine = QStringLiteral("%1 cores, median of %2 runs, each in a fresh process")
                                .arg(QThread::idealThreadCount())
                                .arg(runs);
    std::printf(
        "%s\n\n| triangles | MB | tinyobjloader ms | PhongLab first open ms | ratio | "
        "tinyobjloader MB/s | PhongLab MB/s | tinyobjloader peak MB | PhongLab peak MB: import "
        "child, app |\n|---|---|---|---|---|---|---|---|---|\n",
        qPrintable(machine));
    ChartCsv csv(csvPath);
    csv.note(machine);
    std::vector<double> sizes, tinyMs, ourMs;
    for (double t = 1e4; t <= maxTriangles * 1.01; t *= std::sqrt(10.0)) {
        const auto mesh = sphereOf(t);
        const QString path =
            files.filePath(QStringLiteral("sphere-%1.obj").arg(mesh->triangleCount()));
        const long long triangles = writeObj(*mesh, path);
        if (triangles < 0) {
            std::fprintf(stderr, "cannot write %s\n", qPrintable(path));
            return 1;
        }
        const std::string file = path.toStdString();
        std::vector<Sample> tiny, ours;
        for (int r = 0; r < runs; ++r) { // interleaved: drift falls on both alike
            tiny.push_back(measureInChild([&] { return tinyObjCorners(file) / 3; }));
            ours.push_back(measureInChild([&] { return phonglabFirstOpen(file, cache.path()); }));
        }
        const Sample a = medianOf(tiny), b = medianOf(ours);
        if (a.result != triangles || b.result != triangles) {
            std::fprintf(stderr,
                         "%s: tinyobjloader read %lld triangles, PhongLab %lld, the file "
                         "has %lld\n",
                         file.c_str(), a.result, b.result, triangles);
            return 1;
        }
        const double megabytes = double(QFileInfo(path).size()) / 1e6;
        QFile::remove(path);              // disk: only one file at a time
        constexpr double kMiB = 1.048576; // MB per MiB
        std::printf("| %lld | %.1f | %.1f | %.1f | %.2fx | %.0f | %.0f | %.0f | %.0f, %.0f |\n",
                    a.result, megabytes, a.ms, b.ms, b.ms / a.ms, megabytes / (a.ms / 1e3),
                    megabytes / (b.ms / 1e3), a.peakMiB * kMiB, b.childPeakMiB * kMiB,
                    b.peakMiB * kMiB);
        std::fflush(stdout);
        sizes.push_back(megabytes);
        tinyMs.push_back(a.ms);
        ourMs.push_back(b.ms);
        csv.add(QStringLiteral("import-vs-size"), QStringLiteral("PhongLab first open"), megabytes,
                b.ms);
        csv.add(QStringLiteral("import-vs-size"), QStringLiteral("tinyobjloader"), megabytes, a.ms);
    }
    if (sizes.size() >= 2) {
        const std::size_t top = largestThree(sizes);
        std::printf("\nslope of log(time) on log(MB), all points / largest three: PhongLab %.2f / "
                    "%.2f, tinyobjloader %.2f / %.2f\n",
                    logLogSlope(sizes, ourMs), logLogSlope(sizes, ourMs, top),
                    logLogSlope(sizes, tinyMs), logLogSlope(sizes, tinyMs, top));
    }
    return csv.save() ? 0 : 1;
}
