#!/usr/bin/env bash
# Mesh import benchmark: PhongLab's importer against tinyobjloader, assimp,
# OpenMesh's read_mesh and a bare parse on a ~1.3M-triangle Blender OBJ
# (generated with Blender if missing; not committed), then normal
# computation per method against a plain loop. Prints a table.
#   scripts/bench-import.sh [--runs N]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
if [ ! -f build/bench/bench_icosphere.obj ] || [ ! -f build/bench/bench_icosphere_nonormals.obj ]; then
  command -v blender >/dev/null || { echo "bench-import: needs Blender to make the mesh: apt-get install blender" >&2; exit 1; }
  bash scripts/make-bench-mesh.sh build/bench
fi
exec build/tests/bench/bench_import build/bench/bench_icosphere.obj build/bench/bench_icosphere_nonormals.obj "$@"
