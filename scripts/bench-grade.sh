#!/usr/bin/env bash
# A class graded two ways, in one run on the same machine (compare the
# ratios: this machine is noisy):
#   check loop   what a teacher's shell loop does: `phonglab check --json` once
#                per submission and scene, one after another
#   grade        `phonglab grade`: one child per check, the exact image made once
#                per scene, --jobs 1 and --jobs <cores>
# The class: N submissions (default 40), a quarter each correct, reflect(L, N),
# L not normalised, the ambient term once per light; 2 scenes (check.json,
# default.json) at 800x600. Each way prints its wall time, its ratio to the
# loop, and the CPU it and its children used (user + system): over the cores,
# the floor no number of jobs goes below.
#   scripts/bench-grade.sh [--students N] [--size WxH]
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/bench-class.sh
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
  bench_student_fragment "$i" "$frag" "Ia * ka" "$dir/phong.frag"
done
checks=$((students * ${#scenes[@]}))
cores=$(nproc)
export PHONGLAB_CACHE_DIR="$work/cache" # the same cold mesh cache for each way
unset DISPLAY

# WAY COMMAND...: runs it, sets $WAY (wall seconds) and $WAY_cpu (user + system
# seconds of it and its children: what the cores had to do, whatever the jobs).
measure() {
  local way="$1" t
  shift
  t="$( { TIMEFORMAT='%R %U %S'; time "$@" >/dev/null 2>&1; } 2>&1 )"
  printf -v "$way" '%.2f' "$(echo "$t" | awk '{print $1}')"
  printf -v "${way}_cpu" '%.2f' "$(echo "$t" | awk '{print $2 + $3}')"
}
check_loop() {
  for dir in "$work"/class/*/; do
    for scene in "${scenes[@]}"; do
      "$exe" check "$scene" --fragment "$dir/phong.frag" --size "$size" --json || true
    done
  done
}

measure loop check_loop
measure grade1 "$exe" grade "$work/class" "${scenes[@]/#/--scene=}" --size "$size" --jobs 1 --out "$work/g1"
measure graden "$exe" grade "$work/class" "${scenes[@]/#/--scene=}" --size "$size" --jobs "$cores" --out "$work/gn"

cmp -s <(cut -d, -f1-12,14- "$work/g1/grades.csv") <(cut -d, -f1-12,14- "$work/gn/grades.csv") \
  || { echo "bench-grade: --jobs 1 and --jobs $cores disagree" >&2; exit 1; }
passes=$(grep -c ',pass,' "$work/gn/grades.csv" || true)
echo "bench-grade: $students submissions x ${#scenes[@]} scenes = $checks checks at $size, $cores cores ($passes pass)"
# cpu/cores is the floor no number of jobs goes below on this machine.
printf '  %-28s %8s s  %6s  %8s s  %9s s\n' "way" "wall" "ratio" "cpu" "cpu/cores"
row() {
  printf '  %-28s %8s s  %6.2f  %8s s  %9.2f s\n' "$1" "$2" \
    "$(awk -v a="$2" -v b="$loop" 'BEGIN{print a/b}')" "$3" "$(awk -v c="$3" -v n="$cores" 'BEGIN{print c/n}')"
}
row "check loop ($checks runs)" "$loop" "$loop_cpu"
row "grade --jobs 1" "$grade1" "$grade1_cpu"
row "grade --jobs $cores" "$graden" "$graden_cpu"
printf '  grade --jobs %s / --jobs 1: %.2f\n' "$cores" "$(awk -v a="$graden" -v b="$grade1" 'BEGIN{print a/b}')"
