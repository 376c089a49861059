#pragma once

namespace phonglab::cli {

// phonglab mesh-info FILE [--json] [--normals METHOD] [--crease DEG]
// Loads a mesh exactly as a scene would and reports what came out of it.
// Exit 0 when it loads (warnings included), 1 when it cannot be loaded
// ("phonglab: error: ..." on stderr), 2 on wrong arguments.
int runMeshInfo(int argc, char **argv);

} // namespace phonglab::cli
