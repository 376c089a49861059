#!/usr/bin/env bash
# Running the student's page (check --page, grade --pages) against reading
# it, in one run on the same machine (compare the ratios: this machine is
# noisy):
#   one page     `phonglab check --page` on the Angel-style test project,
#                browser start included (aim: <= 3 s), and `check --capture`
#                of its capture (the same checks without the browser)
#   a class      N projects (default 40; Angel-style and webgl2fundamentals-
#                style in turn) graded on default.json at 800x600: `grade`
#                reading them, `grade --pages` running each page too
#   scripts/bench-pages.sh [--students N] [--jobs N]
set -euo pipefail
cd "$(dirname "$0")/.."
students=40
jobs=$(nproc)
while [ $# -gt 0 ]; do
  case "$1" in
    --students) students="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    *) echo "usage: scripts/bench-pages.sh [--students N] [--jobs N]" >&2; exit 2 ;;
  esac
done
exe=build/app/phonglab
[ -x "$exe" ] || bash scripts/build.sh
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
libraries=(--library tests/data/pages --library assets/meshes)
seconds() { local start=$(date +%s.%N); "$@" > /dev/null 2>&1 || true; echo "$(date +%s.%N) - $start" | bc; }

page=$(seconds "$exe" check --page tests/data/pages/angel "${libraries[@]}" --page-out "$work/one")
again=$(seconds "$exe" check --capture "$work/one/capture.json")
printf 'one page, check --page (browser start included): %6.2f s\n' "$page"
printf 'the same capture, check --capture:               %6.2f s\n' "$again"

for i in $(seq 1 "$students"); do
  project=angel
  [ $((i % 2)) -eq 0 ] && project=webgl2fundamentals
  mkdir -p "$work/class/student$(printf %02d "$i")"
  cp tests/data/pages/$project/* "$work/class/student$(printf %02d "$i")/"
done
static=$(seconds "$exe" grade "$work/class" --scene assets/scenes/default.json --out "$work/static" --jobs "$jobs")
pages=$(seconds "$exe" grade "$work/class" --scene assets/scenes/default.json --out "$work/pages" --jobs "$jobs" --pages "${libraries[@]}")
printf '%d projects, grade --jobs %d (reading them):      %6.1f s\n' "$students" "$jobs" "$static"
printf '%d projects, grade --jobs %d --pages:             %6.1f s (%.2fx, %.2f s more a page)\n' \
  "$students" "$jobs" "$pages" "$(echo "$pages / $static" | bc -l)" "$(echo "($pages - $static) / $students" | bc -l)"
faithful=$(cut -d, -f18 "$work/pages/grades.csv" | tail -n +2 | sort -n | tail -1)
printf 'largest fidelity difference over the class: %s (8-bit steps, outside edges)\n' "$faithful"
