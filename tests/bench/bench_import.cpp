// Mesh import benchmark: PhongLab's importer against tinyobjloader, assimp,
// OpenMesh's read_mesh and a bare parse, on the same file in the same run;
// then normal computation per method against a plain loop over the index
// buffer. Every measurement runs in a fresh child process (fork), so its peak
// memory is its own. Prints a table; not a test.
//
//   bench_import FILE_WITH_NORMALS.obj [FILE_WITHOUT_NORMALS.obj] [--runs N]
#include "mesh/loading/MeshCache.h"
#include "mesh/loading/MeshLoader.h"
#include "mesh/normals/NormalComputation.h"

#include "ChildMeasure.h"
#include "TinyObjLoad.h"

#include "mesh/import/OpenMeshHeaders.h"
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <tiny_obj_loader.h>

#include <QDir>
#include <QTemporaryDir>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <tuple>
#include <unistd.h>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

using Sample = phonglab::bench::ChildSample;
using phonglab::bench::measureInChild;

Sample median(const std::function<long long()> &work, int runs)
{
    std::vector<Sample> samples;
    for (int i = 0; i < runs; ++i)
        samples.push_back(measureInChild(work));
    std::sort(samples.begin(), samples.end(),
              [](const Sample &a, const Sample &b) { return a.ms < b.ms; });
    return samples[samples.size() / 2];
}

// The floor: read the file and turn every v/vn/f number into binary, the
// least any OBJ importer must do.
long long bareParse(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<float> v, vn;
    std::vector<int> f;
    const char *p = text.data(), *end = p + text.size();
    while (p < end) {
        const char *eol = static_cast<const char *>(memchr(p, '\n', size_t(end - p)));
        if (!eol)
            eol = end;
        if (p[0] == 'v' && (p[1] == ' ' || (p[1] == 'n' && p[2] == ' '))) {
            std::vector<float> &out = p[1] == ' ' ? v : vn;
            const char *q = p + (p[1] == ' ' ? 2 : 3);
            for (int i = 0; i < 3; ++i) {
                while (q < eol && *q == ' ')
                    ++q;
                float x = 0;
                q = std::from_chars(q, eol, x).ptr;
                out.push_back(x);
            }
        } else if (p[0] == 'f' && p[1] == ' ') {
            for (const char *q = p + 2; q < eol;) {
                int x = 0;
                auto r = std::from_chars(q, eol, x);
                if (r.ec == std::errc())
                    f.push_back(x);
                q = r.ptr + 1;
            }
        }
        p = eol + 1;
    }
    return static_cast<long long>(v.size() + vn.size() + f.size());
}

long long assimpRead(const std::string &path)
{
    Assimp::Importer importer;
    const aiScene *scene = importer.ReadFile(path, aiProcess_Triangulate);
    long long n = 0;
    if (scene)
        for (unsigned i = 0; i < scene->mNumMeshes; ++i)
            n += scene->mMeshes[i]->mNumFaces;
    return n;
}

long long openMeshRead(const std::string &path)
{
    OpenMesh::TriMesh_ArrayKernelT<> mesh;
    mesh.request_vertex_normals();
    OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexNormal;
    OpenMesh::IO::read_mesh(mesh, path, options);
    return static_cast<long long>(mesh.n_faces());
}

long long phonglabInProcess(const std::string &path)
{
    const phonglab::MeshLoadResult r = phonglab::importMeshFile(QString::fromStdString(path));
    return r.ok() ? r.stats.triangles : -1;
}

// The first open as it was before isolation: parse here, then write the
// cache entry.
long long phonglabInProcessCached(const std::string &path)
{
    const QString file = QString::fromStdString(path);
    const phonglab::MeshLoadResult r = phonglab::importMeshFile(file);
    if (r.ok())
        phonglab::MeshCache::write(file, {}, r);
    return r.ok() ? r.stats.triangles : -1;
}

long long phonglabLoad(const std::string &path)
{
    const phonglab::MeshLoadResult r = phonglab::loadMesh(QString::fromStdString(path));
    return r.ok() ? r.stats.triangles : -1;
}

void printRow(const char *name, const Sample &s, const Sample &peer, const Sample &floor)
{
    std::printf("  %-34s %9.1f ms %9.1f MiB %8.2fx %8.2fx\n", name, s.ms, s.peakMiB, s.ms / peer.ms,
                s.ms / floor.ms);
    std::fflush(stdout);
}

void benchFile(const std::string &path, int runs, const QString &cacheDir)
{
    std::printf("\n%s\n  %-34s %12s %13s %9s %9s\n", path.c_str(), "loader", "time", "peak RSS",
                "vs tinyobj", "vs bare");
    const Sample bare = median([&] { return bareParse(path); }, runs);
    const Sample tiny = median([&] { return phonglab::bench::tinyObjCorners(path); }, runs);
    printRow("bare parse (floor)", bare, tiny, bare);
    printRow("tinyobjloader", tiny, tiny, bare);
    printRow("assimp (Triangulate)", median([&] { return assimpRead(path); }, runs), tiny, bare);
    printRow("OpenMesh read_mesh", median([&] { return openMeshRead(path); }, 1), tiny, bare);
    // Parsed here, without the child process, the cache or its limits: the
    // peer that says what isolation costs.
    const Sample inProcess = median([&] { return phonglabInProcess(path); }, runs);
    printRow("PhongLab importMeshFile, in process", inProcess, tiny, bare);
    const Sample inProcessCached = median(
        [&] {
            QDir(cacheDir).removeRecursively();
            return phonglabInProcessCached(path);
        },
        runs);
    printRow("  + cache write (unisolated open)", inProcessCached, tiny, bare);
    // First open: a cache folder with nothing in it, emptied before each run;
    // the file is parsed in the import child, its answer read back.
    const Sample first = median(
        [&] {
            QDir(cacheDir).removeRecursively();
            return phonglabLoad(path);
        },
        runs);
    printRow("PhongLab loadMesh, first open", first, tiny, bare);
    std::printf("  isolation (child process, limits, answer through the cache format): %+.1f %% of "
                "the parse "
                "in process, %+.1f %% of the unisolated first open\n",
                100.0 * (first.ms / inProcess.ms - 1.0),
                100.0 * (first.ms / inProcessCached.ms - 1.0));
    phonglabLoad(path); // leaves the cache entry for the re-open
    printRow("PhongLab loadMesh, re-open (cache)", median([&] { return phonglabLoad(path); }, runs),
             tiny, bare);
}

// Area-weighted normals in the plainest form: one pass over the index
// buffer accumulating cross products, one pass normalising.
long long plainNormalLoop(const std::vector<glm::vec3> &positions,
                          const std::vector<std::uint32_t> &triangles)
{
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t < triangles.size(); t += 3) {
        const std::uint32_t a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
        const glm::vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        normals[a] += n;
        normals[b] += n;
        normals[c] += n;
    }
    for (glm::vec3 &n : normals)
        n = glm::normalize(n);
    return static_cast<long long>(normals.size());
}

void benchNormals(const std::string &path, int runs)
{
    phonglab::MeshLoadResult r =
        phonglab::loadMesh(QString::fromStdString(path), {phonglab::NormalMethod::Flat, {}});
    if (!r.ok()) {
        std::printf("cannot load %s: %s\n", path.c_str(), qPrintable(r.error));
        return;
    }
    // Weld back to one vertex per position for a fair index buffer.
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> triangles;
    {
        std::vector<std::pair<std::array<float, 3>, std::uint32_t>> keyed;
        for (std::uint32_t i = 0; i < r.mesh->positions.size(); ++i) {
            const glm::vec3 &p = r.mesh->positions[i];
            keyed.push_back({{p.x, p.y, p.z}, i});
        }
        std::sort(keyed.begin(), keyed.end());
        std::vector<std::uint32_t> remap(keyed.size());
        for (std::size_t i = 0; i < keyed.size(); ++i) {
            if (i == 0 || keyed[i].first != keyed[i - 1].first)
                positions.push_back({keyed[i].first[0], keyed[i].first[1], keyed[i].first[2]});
            remap[keyed[i].second] = std::uint32_t(positions.size() - 1);
        }
        for (std::uint32_t i : r.mesh->indices)
            triangles.push_back(remap[i]);
    }
    r.mesh.reset();
    std::printf("\nnormals for %zu positions, %zu triangles\n  %-34s %12s %9s\n", positions.size(),
                triangles.size() / 3, "method", "time", "vs plain");
    const Sample plain = median([&] { return plainNormalLoop(positions, triangles); }, runs);
    std::printf("  %-34s %9.1f ms %8.2fx\n", "plain loop (area-weighted)", plain.ms, 1.0);
    using phonglab::NormalMethod;
    for (auto [name, method, crease] :
         {std::tuple{"flat", NormalMethod::Flat, std::optional<double>()},
          {"average", NormalMethod::Average, std::optional<double>()},
          {"area", NormalMethod::AreaWeighted, std::optional<double>()},
          {"angle", NormalMethod::AngleWeighted, std::optional<double>()},
          {"angle, crease 30 deg", NormalMethod::AngleWeighted, std::optional<double>(30.0)}}) {
        // Bindings captured by copy, by name: clang 14 cannot capture a structured binding.
        const Sample s = median(
            [&, method = method, crease = crease] {
                return static_cast<long long>(
                    phonglab::computeNormals(positions, triangles, method, crease).normals.size());
            },
            runs);
        std::printf("  %-34s %9.1f ms %8.2fx\n", name, s.ms, s.ms / plain.ms);
        std::fflush(stdout);
    }
}

} // namespace

int main(int argc, char **argv)
{
    std::vector<std::string> files;
    int runs = 3;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else
            files.push_back(argv[i]);
    }
    if (files.empty()) {
        std::fprintf(stderr, "usage: bench_import FILE.obj [FILE_NO_NORMALS.obj] [--runs N]\n");
        return 2;
    }
    QTemporaryDir cache;
    qputenv("PHONGLAB_CACHE_DIR", cache.path().toUtf8());
    std::printf("median of %d runs each (OpenMesh: 1 run), each in a fresh process\n", runs);
    for (const std::string &f : files)
        benchFile(f, runs, cache.path());
    benchNormals(files.back(), runs);
    return 0;
}
