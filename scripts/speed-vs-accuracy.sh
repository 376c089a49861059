#!/usr/bin/env bash
# The full speed-against-accuracy run behind docs/speed-vs-accuracy.md: every
# shipped scene (tree and cloud, sphere, torus, grazing plane), every method,
# eight detail levels, 1/4/8 lights and each scene's own, at 800x600, plus
# the normal-method study and the failure pictures. Writes build/bench-full/
# and copies the chart, the tables and the pictures the document shows into
# docs/images/speed-vs-accuracy/. About five minutes on two cores.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
out=build/bench-full
rm -rf "$out"
xvfb-run -a build/app/phonglab bench --images --out "$out" | tee build/bench-full.txt
docs=docs/images/speed-vs-accuracy
mkdir -p "$docs"
cp "$out/chart.png" "$out/normals.png" "$out/results.csv" "$out/fit.csv" "$out/normals.csv" "$docs/"
# The failure modes the document walks through (see its "Where methods fail").
for picture in \
    sphere_gouraud_detail00156 sphere_phong_detail00156 sphere_flat_detail00625 \
    grazing_blinn-phong_detail10000 grazing_phong_detail10000 \
    default_phong_detail00156 default_phong_detail10000 torus_gouraud_detail00625; do
  cp "$out/images/$picture.png" "$docs/$picture.png"
done
echo "wrote $docs"
