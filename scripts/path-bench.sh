#!/usr/bin/env bash
# The camera-path runs behind docs/speed-vs-accuracy.md ("Proof on a moving
# camera"): `phonglab bench --path orbit` and `--path dolly` on the default
# scene (tree and cloud), the sphere, and the 1.3M-triangle icosphere of
# scripts/make-bench-mesh.sh (made first if missing; needs Blender). Writes
# build/path-bench/<path>/ (path.csv, path.png/svg) and the log beside it.
# Usage: scripts/path-bench.sh [--budget SPEC]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
[[ -f build/bench/bench_icosphere.obj ]] || bash scripts/make-bench-mesh.sh build/bench
# The icosphere as a scene: the sphere scene with the icosphere for its mesh.
cat > build/bench/icosphere.json <<'JSON'
{
  "format": 2,
  "mesh": "bench_icosphere.obj",
  "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 45, "near": 0.1, "far": 100},
  "material": {"ka": [0.2, 0.2, 0.2], "kd": [0.7, 0.3, 0.2], "ks": [0.8, 0.8, 0.8], "shininess": 32},
  "ambient": [0.2, 0.2, 0.2],
  "lights": [{"position": [3, 3, 4]}],
  "shading": "phong"
}
JSON
for path in orbit dolly; do
  out=build/path-bench/$path
  mkdir -p "$out"
  xvfb-run -a build/app/phonglab bench --path "$path" "$@" --out "$out" \
    $(for s in assets/scenes/*.json; do printf -- '--scene %s ' "$s"; done) \
    --scene build/bench/icosphere.json | tee "$out/log.txt"
done
