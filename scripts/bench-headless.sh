#!/usr/bin/env bash
# Start-to-PNG time of `phonglab render`, three ways, in one run with the
# runs interleaved (this machine is noisy: compare the ratios):
#   xvfb-run   today's way without a display: xvfb-run -a phonglab render
#   X server   DISPLAY set, an Xvfb already running (the xcb platform, GLX)
#   EGL        no display server at all (phonglab-headless: EGL)
# Prints the median and the ratio of each to xvfb-run.
#   scripts/bench-headless.sh [--runs N] [SCENE.json]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=10
if [ "${1:-}" = "--runs" ]; then runs="$2"; shift 2; fi
scene="${1:-assets/scenes/default.json}"
exe=build/app/phonglab
[ -x "$exe" ] || bash scripts/build.sh
out="$(mktemp -d)"
display=:97
Xvfb "$display" -screen 0 1280x1024x24 -nolisten tcp >/dev/null 2>&1 &
xvfb_pid=$!
trap 'kill $xvfb_pid 2>/dev/null; rm -rf "$out"' EXIT
sleep 1

seconds() { # COMMAND...: wall-clock seconds of one run
  local start end
  start=$(date +%s%N)
  "$@" >/dev/null 2>&1 || { echo "bench-headless: failed: $*" >&2; exit 1; }
  end=$(date +%s%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.4f", (b - a) / 1e9 }'
}
declare -A times
for ((i = 0; i < runs; i++)); do
  times[xvfb]+="$(seconds env -u DISPLAY xvfb-run -a "$exe" render "$scene" -o "$out/a.png") "
  times[x]+="$(seconds env DISPLAY=$display "$exe" render "$scene" -o "$out/b.png") "
  times[egl]+="$(seconds env -u DISPLAY -u WAYLAND_DISPLAY "$exe" render "$scene" -o "$out/c.png") "
done
cmp -s "$out/a.png" "$out/c.png" && same="identical" || same="DIFFERENT"

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR]=$1} END {print (NR%2)?a[(NR+1)/2]:(a[NR/2]+a[NR/2+1])/2}'; }
base=$(echo "${times[xvfb]}" | median)
echo "phonglab render $scene, start to PNG, median of $runs interleaved runs ($(nproc) cores):"
for key in xvfb x egl; do
  m=$(echo "${times[$key]}" | median)
  case $key in
    xvfb) label="xvfb-run -a (today, no display)" ;;
    x) label="X server already running (xcb)" ;;
    egl) label="no display server (EGL)" ;;
  esac
  printf "  %-34s %7.3f s   %.2fx\n" "$label" "$m" "$(awk -v m="$m" -v b="$base" 'BEGIN { print m / b }')"
done
echo "  images of xvfb-run and EGL: $same"
