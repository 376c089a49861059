#!/usr/bin/env bash
# The same class graded as a course platform hands it in and as folders of
# shader files (issue 42), in one run on the same machine, alternated (A B A B)
# so that a change in the machine's load touches both:
#   folders   one folder per student with phong.vert and phong.frag
#   moodle    Moodle's "download all submissions" zip, flat layout: one
#             index.html per student with both shaders inline in a script
#             (template literals), unpacked, regrouped and read as WebGL
#             projects by `grade`
# The class: N students (default 40), a quarter each correct, reflect(L, N),
# L not normalised, the ambient term once per light (WebGL 2 shaders); 2
# scenes (check.json, default.json). Prints both times and their ratio, and
# fails when the two ways disagree on a verdict.
#   scripts/bench-grade-moodle.sh [--students N] [--size WxH] [--jobs N]
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/bench-class.sh
students=40
size=800x600
jobs=$(nproc)
while [ $# -gt 0 ]; do
  case "$1" in
    --students) students="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    *) echo "usage: scripts/bench-grade-moodle.sh [--students N] [--size WxH] [--jobs N]" >&2; exit 2 ;;
  esac
done
exe=build/app/phonglab
[ -x "$exe" ] || bash scripts/build.sh
command -v python3 >/dev/null || { echo "bench-grade-moodle: needs python3 to write the zip" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
scenes=(assets/scenes/check.json assets/scenes/default.json)
vert=assets/shaders/webgl2/phong.vert
frag=assets/shaders/webgl2/phong.frag
mkdir -p "$work/moodle"
for i in $(seq 1 "$students"); do
  name="Student $(printf %02d "$i")_$((1000 + i))"
  dir="$work/folders/$name"
  mkdir -p "$dir"
  cp "$vert" "$dir/phong.vert"
  bench_student_fragment "$i" "$frag" "uAmbientLight * uKa" "$dir/phong.frag"
  {
    printf '<!DOCTYPE html>\n<html><head><title>Lab 3</title></head><body>\n<canvas id="c"></canvas>\n<script>\n'
    printf 'const vsSource = `'; cat "$dir/phong.vert"; printf '`;\n'
    printf 'const fsSource = `'; cat "$dir/phong.frag"; printf '`;\n'
    printf 'const program = initShaderProgram(gl, vsSource, fsSource);\n</script>\n</body></html>\n'
  } > "$work/moodle/${name}_assignsubmission_file_index.html"
done
python3 - "$work/moodle" "$work/download.zip" <<'PY'
import os, sys, zipfile
src, out = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
    for name in sorted(os.listdir(src)):
        z.write(os.path.join(src, name), name)
PY
checks=$((students * ${#scenes[@]}))
export PHONGLAB_CACHE_DIR="$work/cache"
unset DISPLAY
now() { date +%s%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.2f", (b - a) / 1e9 }'; }
run() { # way out
  local input="$work/folders"
  [ "$1" = moodle ] && input="$work/download.zip"
  rm -rf "$2"
  local start; start=$(now)
  "$exe" grade "$input" "${scenes[@]/#/--scene=}" --size "$size" --jobs "$jobs" --out "$2" >/dev/null 2>&1
  since "$start"
}
# A first run of each warms the mesh cache and the shader cache alike.
run folders "$work/warm-f" >/dev/null
run moodle "$work/warm-m" >/dev/null
f1=$(run folders "$work/f1"); m1=$(run moodle "$work/m1")
f2=$(run folders "$work/f2"); m2=$(run moodle "$work/m2")
verdicts() { cut -d, -f1,2,3 "$1/grades.csv" | sed 's/_assignsubmission_file_//' | sort; }
cmp -s <(verdicts "$work/f1") <(verdicts "$work/m1") \
  || { echo "bench-grade-moodle: the two ways disagree on a verdict" >&2; diff <(verdicts "$work/f1") <(verdicts "$work/m1") >&2; exit 1; }
passes=$(grep -c ',pass,' "$work/m1/grades.csv" || true)
echo "bench-grade-moodle: $students students x ${#scenes[@]} scenes = $checks checks at $size, --jobs $jobs ($passes pass)"
printf '  %-40s %8s s %8s s\n' "way" "run 1" "run 2"
printf '  %-40s %8s s %8s s\n' "folders of .vert/.frag" "$f1" "$f2"
printf '  %-40s %8s s %8s s\n' "Moodle zip of HTML projects" "$m1" "$m2"
awk -v f1="$f1" -v f2="$f2" -v m1="$m1" -v m2="$m2" \
  'BEGIN { printf "  moodle / folders: %.3fx (run 1), %.3fx (run 2), %.3fx (sums)\n", m1 / f1, m2 / f2, (m1 + m2) / (f1 + f2) }'
