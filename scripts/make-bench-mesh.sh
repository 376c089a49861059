#!/usr/bin/env bash
# Generates the load-time benchmark meshes with Blender (not committed):
#   OUT_DIR/bench_icosphere.obj            ~1.3 million triangles, with normals
#   OUT_DIR/bench_icosphere_nonormals.obj  the same mesh without normals
# Usage: scripts/make-bench-mesh.sh [OUT_DIR]   (default: build/bench)
# Needs Blender 3.4 or later on PATH (Debian: apt-get install blender), or
# BLENDER=/path/to/blender.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build/bench}"
blender="${BLENDER:-blender}"
if ! command -v "$blender" >/dev/null; then
  echo "make-bench-mesh: blender not found (install it, e.g. apt-get install blender, or set BLENDER)" >&2
  exit 1
fi
echo "make-bench-mesh: $("$blender" --version 2>/dev/null | head -n 1), writing to $out"
mkdir -p "$out"
"$blender" -b --factory-startup -P assets/blender/make_bench_mesh.py -- "$out" 2>&1 \
  | grep -v -e '^Blender quit$' -e '^Read prefs' -e '^$'
ls -l "$out"/bench_icosphere*.obj
