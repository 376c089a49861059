#!/usr/bin/env bash
# What a user feels while working, each against its floor, with ratios
# (docs/performance.md): the viewport's presented frame against a raw-GL
# window (bench_frame), edit to pixel and the longest GUI stall against raw
# GL (bench_edit_latency), and mesh import against tinyobjloader
# (scripts/bench-import.sh; needs Blender once to make its 1.3M-triangle
# mesh); then how each cost grows, with its charts (scripts/bench-scaling.sh:
# frame beside raw GL, reference, memory and import against size). Under
# Xvfb when there is no display. About 15 minutes.
#   scripts/bench-interactive.sh [--quick]     (--quick: fewer frames and edits, no import,
#                                               the scaling sweep small, its charts in build/)
set -euo pipefail
cd "$(dirname "$0")/.."
frames=200
edits=20
import=1
scaling=()
if [ "${1:-}" = "--quick" ]; then
  frames=60
  edits=5
  import=0
  scaling=(--quick)
fi
bash scripts/build.sh
run=()
if [ -z "${DISPLAY:-}" ]; then
  run=(xvfb-run -a -s "-screen 0 1920x1080x24")
fi
echo "== the viewport's frame against a raw-GL window that presents (bench_frame)"
"${run[@]}" build/tests/bench/bench_frame --frames "$frames"
echo
echo "== edit to pixel and the longest GUI stall (bench_edit_latency)"
"${run[@]}" build/tests/bench/bench_edit_latency --edits "$edits"
if [ "$import" = 1 ]; then
  echo
  echo "== mesh import against tinyobjloader (scripts/bench-import.sh)"
  bash scripts/bench-import.sh
fi
echo
echo "== how each cost grows, with charts (scripts/bench-scaling.sh)"
bash scripts/bench-scaling.sh "${scaling[@]}"
