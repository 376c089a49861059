#pragma once
#include "MeshLoader.h"

#include <QString>

namespace phonglab {

// Mesh files are parsed in a child process: the same `phonglab` binary run
// as `phonglab __import-mesh`, under a wall-clock limit and setrlimit limits
// on address space and CPU time. Third-party readers (OpenMesh's PLY reader
// has looped forever on a malformed header) then cost an error message,
// never the app's memory, its responsiveness or the user's unsaved work. The
// child hands its result back as a MeshCache entry, which this process
// reads with the same checks as any cache file and then keeps in the cache.
struct MeshImportLimits {
    int wallClockMs = 0;          // the child is killed after this
    qint64 addressSpaceBytes = 0; // RLIMIT_AS; 0: none (sanitizer builds reserve terabytes)
    int cpuSeconds = 0;           // RLIMIT_CPU

    // Generous for honest files (a 100 MB OBJ parses in about a second):
    // 30 s plus 1 s per 2 MB, 2 GiB plus 40 bytes of address space per byte
    // of file. PHONGLAB_IMPORT_TIMEOUT_S and PHONGLAB_IMPORT_MEMORY_MB
    // override them (tests, very large files).
    static MeshImportLimits forFile(qint64 fileBytes);
};

// Exit statuses of `phonglab __import-mesh` beyond the CLI's 0/1/2.
inline constexpr int kImportExitOutOfMemory = 3;

// Runs the child and waits for it, calling progress() with what it reports
// (false cancels: the child is killed at once). Errors name the file and say
// what happened: a load error as the reader put it, "the reader stopped
// answering after N s", "ran out of memory", "crashed with signal N".
MeshLoadResult importMeshIsolated(const QString &path, const NormalOptions &normals,
                                  const LoadProgress &progress);

// The child's side: applies `limits` to this process, imports `path` in
// process, writes the result to `entryFile` in MeshCache's format and
// reports "progress F" / "error MESSAGE" lines on stdout. Returns the exit
// status.
int runMeshImportChild(const QString &path, const NormalOptions &normals, const QString &entryFile,
                       const MeshImportLimits &limits);

} // namespace phonglab
