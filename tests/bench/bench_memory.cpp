// Memory per million triangles (prints figures; not a test): for UV spheres
// of growing size, each measured in a fresh child process so that no size
// inherits another's heap, the bytes PhongLab holds at each step against the
// minimum (positions + normals as floats, 32-bit indices):
//   - the MeshData on the CPU (its vectors, and the resident growth);
//   - the peak while uploading it (GpuMesh::upload's temporaries and the
//     driver's copy) and what stays after the renderer drops the CPU copy;
//   - the GPU buffers uploaded (one interleaved vertex buffer, one index
//     buffer; with "detail": "auto" the index buffer also holds every level),
//     and the driver's own count where it gives one (NVIDIA, AMD);
//   - the exact reference's BVH (its structure, and the peak of its build).
// Then where each stops fitting: the triangle count that fills this
// machine's RAM, and the GPU's memory where the driver reports it.
//
//   build/tests/bench/bench_memory [--max-triangles N] [--csv FILE]
#include "ChartCsv.h"
#include "GpuMemoryInfo.h"
#include "LogLogFit.h"
#include "ProcessMemory.h"
#include "ScalingMeshes.h"
#include "core/reference/MeshBvh.h"
#include "headless/HeadlessPlatform.h"
#include "mesh/detail/DetailLevels.h"
#include "render/draw/OffscreenRenderer.h"

#include <QGuiApplication>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace phonglab;
using namespace phonglab::bench;

namespace {

// Bytes, measured in one child; plain data, passed back through a pipe.
struct MemoryRow {
    double triangles = 0, vertices = 0;
    double minimum = 0;     // 24 per vertex + 4 per index
    double meshData = 0;    // the MeshData's vectors (capacity)
    double meshPeak = 0;    // resident peak growth while making it
    double uploadPeak = 0;  // resident peak while uploading, the CPU mesh still held
    double stays = 0;       // resident growth after the CPU copy is freed and a frame drawn
    double gpuBuffers = 0;  // what GpuMesh uploads at "detail" 1
    double autoLevels = -1; // the further index bytes of "detail": "auto"; -1 not measured
    double gpuMeasured = -1, gpuTotal = -1; // from the driver; -1 not reported
    double bvhStructure = 0;                // MeshBvh's nodes, vertex copies and triangle ids
    double bvhPeak = 0;                     // resident peak growth while building it
    double ramBytes = 0;
    char renderer[96] = {};
    char gpuSource[32] = {};
};

constexpr double kLevelsUpTo = 1.1e6; // auto detail's levels take long to build beyond

double vectorBytes(const MeshData &m)
{
    return double(m.positions.capacity() * sizeof(glm::vec3)
                  + m.normals.capacity() * sizeof(glm::vec3)
                  + m.indices.capacity() * sizeof(std::uint32_t));
}

void measureBvh(const MeshData &mesh, MemoryRow &row)
{
    resetPeakResident();
    const double before = double(residentBytes());
    const MeshBvh bvh(mesh);
    row.bvhPeak = double(peakResidentBytes()) - before;
    row.bvhStructure = double(bvh.nodeCount() * sizeof(MeshBvh::Node))
        + double(bvh.triangleCount()) * (3 * sizeof(glm::vec3) + sizeof(std::uint32_t));
}

double autoLevelIndexBytes(const MeshData &mesh)
{
    const DetailLevels levels = buildDetailLevels(mesh);
    double bytes = 0;
    for (std::size_t i = 1; i < levels.levels.size(); ++i)
        bytes += double(levels.levels[i].indices.size() * sizeof(std::uint32_t));
    return bytes;
}

// In the child: everything for one size; false when GL is missing.
bool measureOne(double triangles, MemoryRow &row)
{
    chooseCommandPlatform();
    int argc = 1;
    char name[] = "bench_memory";
    char *argv[] = {name, nullptr};
    QGuiApplication app(argc, argv);
    OffscreenRenderer gl;
    if (const Result<> created = gl.create(); !created) {
        std::fprintf(stderr, "%s\n", qPrintable(created.error()));
        return false;
    }
    std::strncpy(row.renderer, qPrintable(gl.glRendererName()), sizeof row.renderer - 1);
    gl.renderImage(QSize(800, 600)); // the target exists before the baseline
    const double base = double(residentBytes());
    resetPeakResident();
    std::shared_ptr<const MeshData> mesh = sphereOf(triangles);
    row.meshPeak = double(peakResidentBytes()) - base;
    row.triangles = double(mesh->triangleCount());
    row.vertices = double(mesh->positions.size());
    row.minimum = minimumBytes(*mesh);
    row.meshData = vectorBytes(*mesh);
    row.gpuBuffers = row.vertices * 6 * sizeof(float) + double(mesh->indices.size()) * 4;
    measureBvh(*mesh, row);
    if (triangles <= kLevelsUpTo)
        row.autoLevels = autoLevelIndexBytes(*mesh);

    gl.makeCurrent();
    const GpuMemoryInfo before = queryGpuMemory();
    resetPeakResident();
    const Scene scene = sphereScene(*mesh);
    if (const Result<> set = gl.renderer().setScene(scene, meshesOf(scene, mesh)); !set) {
        std::fprintf(stderr, "%s\n", qPrintable(set.error()));
        return false;
    }
    row.uploadPeak = double(peakResidentBytes()) - base;
    gl.renderer().updateSceneParameters(scene);
    mesh.reset(); // the renderer dropped its reference: this frees the CPU copy
    gl.renderImage(QSize(800, 600));
    // Freed heap pages go back to the system, so what stays is what is held.
    malloc_trim(0);
    row.stays = double(residentBytes()) - base;
    const GpuMemoryInfo after = queryGpuMemory();
    if (before.availableBytes >= 0)
        row.gpuMeasured = double(before.availableBytes - after.availableBytes);
    row.gpuTotal = double(after.totalBytes);
    std::strncpy(row.gpuSource, after.source, sizeof row.gpuSource - 1);
    row.ramBytes = double(physicalMemoryBytes());
    return true;
}

// Runs measureOne() in a fresh process (Qt and GL are started only there).
bool measureInChild(double triangles, MemoryRow &row)
{
    int fds[2];
    if (pipe(fds) != 0)
        return false;
    std::fflush(stdout);
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        MemoryRow measured;
        const bool ok = measureOne(triangles, measured);
        if (ok)
            (void)!write(fds[1], &measured, sizeof measured);
        _exit(ok ? 0 : 1);
    }
    close(fds[1]);
    const bool got = read(fds[0], &row, sizeof row) == ssize_t(sizeof row);
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    return got && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

double mb(double bytes)
{
    return bytes / 1e6;
}

// Bytes per triangle to "MB per million triangles": the same number.
double perTriangle(double bytes, const MemoryRow &row)
{
    return bytes / row.triangles;
}

void printRow(const MemoryRow &r)
{
    std::printf("| %.0f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %s | %s | %.1f | %.1f |\n",
                r.triangles, mb(r.minimum), mb(r.meshData), mb(r.meshPeak), mb(r.uploadPeak),
                mb(r.stays), mb(r.gpuBuffers),
                r.autoLevels >= 0 ? qPrintable(QString::number(mb(r.autoLevels), 'f', 1)) : "-",
                r.gpuMeasured >= 0 ? qPrintable(QString::number(mb(r.gpuMeasured), 'f', 1)) : "-",
                mb(r.bvhStructure), mb(r.bvhPeak));
    std::fflush(stdout);
}

void printPerMillion(const std::vector<MemoryRow> &rows)
{
    const MemoryRow &r = rows.back();
    const double min = perTriangle(r.minimum, r);
    const auto line = [&](const char *what, double bytes) {
        std::printf("| %s | %.1f | %.2fx |\n", what, perTriangle(bytes, r),
                    perTriangle(bytes, r) / min);
    };
    std::printf("\nper million triangles at %.0f triangles (MB; x the minimum):\n\n"
                "| what | MB per million triangles | x minimum |\n|---|---|---|\n",
                r.triangles);
    line("minimum: positions + normals (floats) + 32-bit indices", r.minimum);
    line("CPU: the MeshData", r.meshData);
    line("CPU: peak while making the mesh", r.meshPeak);
    line("CPU: peak while uploading (mesh held)", r.uploadPeak);
    line("CPU: stays after upload, CPU copy freed, one frame", r.stays);
    line("GPU: buffers uploaded (\"detail\" 1)", r.gpuBuffers);
    if (r.gpuMeasured >= 0)
        line("GPU: the driver's count", r.gpuMeasured);
    for (auto it = rows.rbegin(); it != rows.rend(); ++it)
        if (it->autoLevels >= 0) { // measured on a smaller mesh: its own ratio
            std::printf("| GPU: + the levels of \"detail\": \"auto\" (at %.0f triangles) | %.1f | "
                        "%.2fx |\n",
                        it->triangles, it->autoLevels / it->triangles,
                        it->autoLevels / it->minimum);
            break;
        }
    line("reference: BVH structure", r.bvhStructure);
    line("reference: peak while building the BVH", r.bvhPeak);
}

void printWhereItStops(const MemoryRow &r)
{
    const auto fills = [&](double memory, double bytes) { return memory / perTriangle(bytes, r); };
    std::printf("\nwhere it stops fitting (this machine: %.1f GB of RAM; %s):\n",
                mb(r.ramBytes) / 1e3, r.gpuSource);
    std::printf("- loading and uploading (CPU peak): %.0f M triangles fill the RAM\n",
                fills(r.ramBytes, r.uploadPeak) / 1e6);
    if (r.gpuTotal > 0)
        std::printf("- the GPU's %.1f GB: %.0f M triangles of buffers\n", mb(r.gpuTotal) / 1e3,
                    fills(r.gpuTotal, r.gpuMeasured > 0 ? r.gpuMeasured : r.gpuBuffers) / 1e6);
    else
        std::printf("- no GPU memory reported (%s); where the driver keeps its buffers in this "
                    "process (llvmpipe), what stays after upload fills the RAM at %.0f M "
                    "triangles\n",
                    r.renderer, fills(r.ramBytes, r.stays) / 1e6);
    std::printf("- the reference (mesh + BVH build peak): %.0f M triangles fill the RAM\n",
                fills(r.ramBytes, r.meshData + r.bvhPeak) / 1e6);
    std::printf("- one draw call counts indices in a GLsizei: at most %.0f M triangles per "
                "mesh, whatever the memory\n",
                double(0x7fffffff / 3) / 1e6);
}

void addToCsv(ChartCsv &csv, const MemoryRow &r)
{
    const QString chart = QStringLiteral("memory-vs-triangles");
    // The GPU buffers are the minimum byte for byte here: one line for both.
    csv.add(chart, QStringLiteral("minimum = GPU buffers"), r.triangles, mb(r.minimum));
    csv.add(chart, QStringLiteral("upload peak"), r.triangles, mb(r.uploadPeak));
    csv.add(chart, QStringLiteral("after upload"), r.triangles, mb(r.stays));
    csv.add(chart, QStringLiteral("BVH build peak"), r.triangles, mb(r.bvhPeak));
}

} // namespace

int main(int argc, char **argv)
{
    double maxTriangles = 1e7;
    QString csvPath;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--max-triangles") == 0 && i + 1 < argc)
            maxTriangles = std::atof(argv[++i]);
        else if (std::strcmp(argv[i], "--csv") == 0 && i + 1 < argc)
            csvPath = QString::fromLocal8Bit(argv[++i]);
        else {
            std::fprintf(stderr, "usage: bench_memory [--max-triangles N] [--csv FILE]\n");
            return 2;
        }
    }
    std::printf("resident memory in MB (10^6 bytes) over a baseline with the context made; each "
                "size in a fresh process\n\n| triangles | minimum | MeshData | mesh peak | upload "
                "peak | stays | GPU buffers | + auto levels | GPU (driver) | BVH | BVH build peak "
                "|\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    ChartCsv csv(csvPath);
    std::vector<MemoryRow> rows;
    for (double t = 1e5; t <= maxTriangles * 1.01; t *= std::sqrt(10.0)) {
        MemoryRow row;
        if (!measureInChild(t, row)) {
            std::fprintf(stderr, "the %.0f-triangle child failed\n", t);
            return 1;
        }
        printRow(row);
        addToCsv(csv, row);
        rows.push_back(row);
    }
    if (rows.empty())
        return 1;
    csv.note(QStringLiteral("%1, %2 GB RAM")
                 .arg(QString::fromLatin1(rows.back().renderer))
                 .arg(mb(rows.back().ramBytes) / 1e3, 0, 'f', 1));
    std::vector<double> x, up;
    for (const MemoryRow &r : rows) {
        x.push_back(r.triangles);
        up.push_back(r.uploadPeak);
    }
    if (x.size() >= 2)
        std::printf("\nslope of log(upload peak) on log(triangles): %.2f\n", logLogSlope(x, up));
    printPerMillion(rows);
    printWhereItStops(rows.back());
    return csv.save() ? 0 : 1;
}
