#!/usr/bin/env bash
# What a user feels, before and after a change, in one run: the frame the
# viewport presents (bench_frame, 800x600), edit to pixel on the default
# path, the app's (bench_edit_latency) and the whole `phonglab bench --quick` sweep
# (its mean frame time), for REV (a git worktree built in build-before/,
# compiler cache shared) and for this tree (build/), in alternating rounds
# so that a change in the machine's load touches both sides. Each figure is
# also set against its peer in the same run (raw GL), and the table gives
# the median over the rounds and after/before.
#   scripts/bench-before-after.sh --before REV [--rounds N]
set -euo pipefail
cd "$(dirname "$0")/.."
before=""
rounds=3
while [ $# -gt 0 ]; do
  case "$1" in
    --before) before="$2"; shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    *) echo "usage: scripts/bench-before-after.sh --before REV [--rounds N]" >&2; exit 2 ;;
  esac
done
[ -n "$before" ] || { echo "usage: scripts/bench-before-after.sh --before REV [--rounds N]" >&2; exit 2; }
rev="$(git rev-parse --verify "$before^{commit}")"
targets=(phonglab bench_frame bench_edit_latency)
bash scripts/build.sh >/dev/null
cmake --build build --target "${targets[@]}" >/dev/null

src="build-before/src"
if [ "$(git -C "$src" rev-parse HEAD 2>/dev/null || true)" != "$rev" ]; then
  git worktree remove --force "$src" >/dev/null 2>&1 || rm -rf "$src"
  git worktree prune
  git worktree add --detach "$src" "$rev" >/dev/null 2>&1
fi
echo "bench-before-after: building $before (${rev:0:7}) in build-before/ ..." >&2
cmake -S "$src" -B build-before/build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null
cmake --build build-before/build --parallel "$(nproc)" --target "${targets[@]}" >/dev/null

run=()
if [ -z "${DISPLAY:-}" ]; then
  run=(xvfb-run -a -s "-screen 0 1920x1080x24")
fi
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
# DIR SIDE ROUND: one round of the three figures, appended to $out/figures
measure() {
  local dir="$1" side="$2" round="$3" log="$out/$2-$3"
  "${run[@]}" "$dir/tests/bench/bench_frame" --frames 60 >"$log.frame" 2>&1
  "${run[@]}" "$dir/tests/bench/bench_edit_latency" --edits 10 >"$log.edit" 2>&1
  "${run[@]}" "$dir/app/phonglab" bench --quick --out "$log.sweep" >"$log.bench" 2>&1
  # The viewport's frame at 800x600 and the raw GL window's draw + swap.
  awk -F'|' -v s="$side" '$2 ~ /800x600/ && $3 ~ /viewport \(frame as presented\)/ { gsub(/ /, "", $7); print s, "frame_ms", $7 }
    $2 ~ /800x600/ && $3 ~ /raw GL, own window/ { split($4, d, " "); split($8, w, " "); print s, "frame_raw_ms", d[2] + w[2] }' \
    "$log.frame" >>"$out/figures"
  # Edit to pixel: PhongLab's default path and the raw GL one.
  awk -F'|' -v s="$side" '$2 ~ /^ raw GL/ { split($3, m, " "); print s, "edit_raw_ms", m[1] }
    $2 ~ /^ PhongLab: worker, warm-up in lent viewport context \(the app\)/ { split($3, m, " "); print s, "edit_ms", m[1] }' \
    "$log.edit" >>"$out/figures"
  # The sweep: the mean frame time of all its configurations.
  awk -F, -v s="$side" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "frame_ms") c = i; next }
    c { t += $c; n++ } END { if (n) print s, "sweep_ms", t / n }' \
    "$log.sweep/results.csv" >>"$out/figures"
  echo "bench-before-after: round $round, $side done" >&2
}
for ((r = 1; r <= rounds; r++)); do
  if ((r % 2)); then
    measure build-before/build before "$r"
    measure build after "$r"
  else
    measure build after "$r"
    measure build-before/build before "$r"
  fi
done
echo "| figure (median of $rounds rounds) | before ${rev:0:7} | after | after / before |"
echo "|---|---|---|---|"
python3 - "$out/figures" <<'PY'
import statistics, sys
rows = {}
for line in open(sys.argv[1]):
    side, name, value = line.split()
    rows.setdefault(name, {}).setdefault(side, []).append(float(value))
def med(name, side):
    values = rows.get(name, {}).get(side, [])
    return statistics.median(values) if values else float('nan')
labels = [("frame_ms", "viewport frame, 800x600 (ms)"), ("frame_raw_ms", "  its peer: raw GL draw + swap (ms)"),
          ("edit_ms", "edit to pixel, default path (ms)"), ("edit_raw_ms", "  its peer: raw GL (ms)"),
          ("sweep_ms", "bench --quick, mean frame (ms)")]
for name, label in labels:
    b, a = med(name, "before"), med(name, "after")
    print(f"| {label} | {b:.2f} | {a:.2f} | {a / b:.2f}x |")
for name, peer, label in [("frame_ms", "frame_raw_ms", "viewport / raw GL"), ("edit_ms", "edit_raw_ms", "edit / raw GL")]:
    print(f"| {label} | {med(name, 'before') / med(peer, 'before'):.2f}x | {med(name, 'after') / med(peer, 'after'):.2f}x | |")
PY
echo "load at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
