#!/usr/bin/env bash
# How long a first build takes on this machine, from scratch and without a
# compiler cache, the way a new contributor or a fresh CI machine meets it:
#   app     `cmake --build B --target phonglab`: what scripts/run.sh builds
#   tree    the whole plain tree (app, tests, benchmarks, tools)
# With --before REV, the same two builds of REV (a git worktree of it) run
# first in the same invocation, and the table shows both and their ratio.
# --app-only skips the whole tree (about a fifth of the time).
#   scripts/build-time.sh [--before REV] [--jobs N] [--app-only]
set -euo pipefail
cd "$(dirname "$0")/.."
before=""
jobs="$(nproc)"
app_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --before) before="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --app-only) app_only=1; shift ;;
    *) echo "usage: scripts/build-time.sh [--before REV] [--jobs N] [--app-only]" >&2; exit 2 ;;
  esac
done
bash scripts/setup.sh >/dev/null
work="$(mktemp -d)"
trap 'git worktree remove --force "$work/before" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT

now() { date +%s%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", (b - a) / 1e9 }'; }

# SOURCE BUILD_DIR: prints "APP_SECONDS TREE_SECONDS"
measure() {
  local src="$1" dir="$2" start app tree
  # No compiler cache: the launcher is left empty on purpose.
  cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER_LAUNCHER= >/dev/null
  start=$(now)
  cmake --build "$dir" --parallel "$jobs" --target phonglab >/dev/null
  app=$(since "$start")
  if [ "$app_only" = 1 ]; then
    echo "$app 0 $(ninja -C "$dir" -t commands phonglab 2>/dev/null | wc -l)"
    return
  fi
  rm -rf "$dir"
  cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER_LAUNCHER= >/dev/null
  start=$(now)
  cmake --build "$dir" --parallel "$jobs" >/dev/null
  tree=$(since "$start")
  echo "$app $tree $(ninja -C "$dir" -t commands 2>/dev/null | wc -l)"
}

minutes() { awk -v s="$1" 'BEGIN { printf "%.1f min", s / 60 }'; }

if [ -n "$before" ]; then
  git worktree add --detach "$work/before" "$before" >/dev/null 2>&1
  echo "build-time: measuring $before ..." >&2
  read -r app0 tree0 targets0 < <(measure "$work/before" "$work/build-before")
fi
echo "build-time: measuring the working tree ..." >&2
read -r app1 tree1 targets1 < <(measure "$PWD" "$work/build-now")

echo "build-time: from scratch, no compiler cache, $jobs jobs, $(nproc) cores"
if [ -n "$before" ]; then
  printf '  %-12s %12s %12s %8s\n' "build" "$before" "now" "ratio"
  printf '  %-12s %12s %12s %8s\n' "app" "$(minutes "$app0")" "$(minutes "$app1")" \
    "$(awk -v a="$app1" -v b="$app0" 'BEGIN { printf "%.2f", a / b }')"
  [ "$app_only" = 1 ] ||
    printf '  %-12s %12s %12s %8s\n' "whole tree" "$(minutes "$tree0")" "$(minutes "$tree1")" \
      "$(awk -v a="$tree1" -v b="$tree0" 'BEGIN { printf "%.2f", a / b }')"
  printf '  %-12s %12s %12s\n' "build steps" "$targets0" "$targets1"
else
  printf '  %-12s %12s\n' "app" "$(minutes "$app1")"
  [ "$app_only" = 1 ] || printf '  %-12s %12s\n' "whole tree" "$(minutes "$tree1")"
  printf '  %-12s %12s\n' "build steps" "$targets1"
fi
