#pragma once

namespace phonglab::cli {

// phonglab __import-mesh --normals METHOD [--crease DEG] --out ENTRY
//                        --address-space-mb N --cpu-seconds N -- FILE
// Internal: the child process of importMeshIsolated(). Not for people; the
// parent builds these arguments and reads the answer (MeshImportProcess.h).
int runImportMesh(int argc, char **argv);

} // namespace phonglab::cli
