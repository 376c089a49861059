#!/usr/bin/env bash
# How each cost grows (docs/performance.md, "How each cost grows"): the
# frame beside a raw-GL frame and the exact reference against triangles and
# pixels (bench_scaling), memory per million triangles against the minimum
# and where it stops fitting (bench_memory), import time against file size
# beside tinyobjloader (bench_import_scaling); each prints its table,
# ratios and slopes, writes a CSV, and bench_charts draws the PNG charts.
# No display server needed. About 5 minutes on 2 cores with llvmpipe.
#   scripts/bench-scaling.sh [--quick] [--out DIR]
#     default: up to 10^7 triangles, charts and CSVs into docs/images/scaling
#     --quick: up to 10^5 triangles (memory 10^6), 3 frames, 1 import run,
#              into build/bench/scaling-quick (under a minute)
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/images/scaling
frames=10
triangles=1e7
memory_triangles=1e7
import_triangles=3.2e6
runs=3
while [ $# -gt 0 ]; do
  case "$1" in
    --quick)
      out=build/bench/scaling-quick
      frames=3
      triangles=1e5
      memory_triangles=1e6
      import_triangles=1e5
      runs=1
      ;;
    --out) out="$2"; shift ;;
    *) echo "usage: scripts/bench-scaling.sh [--quick] [--out DIR]" >&2; exit 2 ;;
  esac
  shift
done
# A configured build needs only these targets (phonglab: the import child);
# a first run builds everything.
if [ -f build/build.ninja ]; then
  cmake --build build --target bench_scaling bench_memory bench_import_scaling bench_charts phonglab
else
  bash scripts/build.sh
fi
mkdir -p "$out"
bench=build/tests/bench
echo "== the frame beside raw GL, and the reference, against triangles and pixels (bench_scaling)"
"$bench/bench_scaling" --max-triangles "$triangles" --frames "$frames" --csv "$out/scaling.csv"
echo
echo "== memory per million triangles against the minimum (bench_memory)"
"$bench/bench_memory" --max-triangles "$memory_triangles" --csv "$out/memory.csv"
echo
echo "== import time against file size, beside tinyobjloader (bench_import_scaling)"
"$bench/bench_import_scaling" --max-triangles "$import_triangles" --runs "$runs" --csv "$out/import.csv"
echo
echo "== charts (bench_charts)"
"$bench/bench_charts" "$out" "$out/scaling.csv" "$out/memory.csv" "$out/import.csv"
