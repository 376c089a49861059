#!/usr/bin/env bash
# A class graded two ways, in one run on the same machine (compare the
# ratios: this machine is noisy):
#   check loop   what a teacher's shell loop does: `phonglab check --json` once
#                per submission and scene, one after another
#   grade        `phonglab grade`: one child per check, the exact image made once
#                per scene, --jobs 1 and --jobs <cores>
# The class: N submissions (default 40), a quarter each correct, reflect(L, N),
# L not normalised, the ambient term once per light; 2 scenes (check.json,
# default.json) at 800x600.
#   scripts/bench-grade.sh [--students N] [--size WxH]
set -euo pipefail
cd "$(dirname "$0")/.."
students=40
size=800x600
while [ $# -gt 0 ]; do
  case "$1" in
    --students) students="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    *) echo "usage: scripts/bench-grade.sh [--students N] [--size WxH]" >&2; exit 2 ;;
  esac
done
exe=build/app/phonglab
[ -x "$exe" ] || bash scripts/build.sh
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
scenes=(assets/scenes/check.json assets/scenes/default.json)
frag=shaders/phong.frag
for i in $(seq 1 "$students"); do
  dir="$work/class/student$(printf %02d "$i")"
  mkdir -p "$dir"
  case $((i % 4)) in
    0) cp "$frag" "$dir/phong.frag" ;;
    1) sed 's/reflect(-L, N)/reflect(L, N)/' "$frag" > "$dir/phong.frag" ;;
    2) sed 's|vec3 L = toLight / d;|vec3 L = toLight;|' "$frag" > "$dir/phong.frag" ;;
    3) sed 's|I += fatt \* (|I += Ia * ka + fatt * (|' "$frag" > "$dir/phong.frag" ;;
  esac
done
checks=$((students * ${#scenes[@]}))
cores=$(nproc)
export PHONGLAB_CACHE_DIR="$work/cache" # the same cold mesh cache for each way
unset DISPLAY

now() { date +%s%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.2f", (b - a) / 1e9 }'; }

start=$(now)
for dir in "$work"/class/*/; do
  for scene in "${scenes[@]}"; do
    "$exe" check "$scene" --fragment "$dir/phong.frag" --size "$size" --json >/dev/null 2>&1 || true
  done
done
loop=$(since "$start")

start=$(now)
"$exe" grade "$work/class" "${scenes[@]/#/--scene=}" --size "$size" --jobs 1 --out "$work/g1" >/dev/null 2>&1
grade1=$(since "$start")

start=$(now)
"$exe" grade "$work/class" "${scenes[@]/#/--scene=}" --size "$size" --jobs "$cores" --out "$work/gn" >/dev/null 2>&1
graden=$(since "$start")

cmp -s <(cut -d, -f1-12,14- "$work/g1/grades.csv") <(cut -d, -f1-12,14- "$work/gn/grades.csv") \
  || { echo "bench-grade: --jobs 1 and --jobs $cores disagree" >&2; exit 1; }
passes=$(grep -c ',pass,' "$work/gn/grades.csv" || true)
echo "bench-grade: $students submissions x ${#scenes[@]} scenes = $checks checks at $size, $cores cores ($passes pass)"
printf '  %-28s %8s s  %6s\n' "way" "wall" "ratio"
printf '  %-28s %8s s  %6s\n' "check loop ($checks runs)" "$loop" "1.00"
printf '  %-28s %8s s  %6.2f\n' "grade --jobs 1" "$grade1" "$(awk -v a="$grade1" -v b="$loop" 'BEGIN{print a/b}')"
printf '  %-28s %8s s  %6.2f\n' "grade --jobs $cores" "$graden" "$(awk -v a="$graden" -v b="$loop" 'BEGIN{print a/b}')"
