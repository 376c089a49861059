#!/usr/bin/env bash
# Renders the thumbnail of every shipped scene (File → Examples) with the
# CLI: assets/scenes/NAME.json → assets/scenes/thumbnails/NAME.png, 128x96.
# Re-run it after changing a scene, then re-run cmake so the binary embeds
# the new pictures (tests/ui/tst_examplesmenu checks every scene has one).
#
#   scripts/make-thumbnails.sh [BUILD_DIR]     (default: build; it must hold app/phonglab)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
exe="$build/app/phonglab"
if [ ! -x "$exe" ]; then
  echo "make-thumbnails: $exe not found; build first (scripts/build.sh)" >&2
  exit 1
fi
# render needs no display server (EGL without one).
mkdir -p assets/scenes/thumbnails
for scene in assets/scenes/*.json; do
  name=$(basename "$scene" .json)
  "$exe" render "$scene" -o "assets/scenes/thumbnails/$name.png" --size 128x96
  echo "assets/scenes/thumbnails/$name.png"
done
