#!/usr/bin/env bash
# Builds the libFuzzer targets (build-sanitize/, clang 14, ASan + UBSan; see
# tests/fuzz/CMakeLists.txt) and runs them.
#
#   scripts/fuzz.sh [TARGET|all] [SECONDS]   fuzz each target for SECONDS (default 60)
#   scripts/fuzz.sh --runs N [TARGET|all]    fuzz each target for N executions
#   scripts/fuzz.sh --replay [TARGET|all]    run every seed (tests/fuzz/corpus/<t>) and
#                                            every regression input (tests/data/fuzz/<t>)
#                                            once, no fuzzing (CI)
#   scripts/fuzz.sh --make-seeds             rewrite the binary seeds (OM, binary PLY/STL/OFF,
#                                            mesh cache entries)
#   scripts/fuzz.sh --list                   the targets
#
# Fuzzing starts from a fresh copy of the seed corpus in
# build-sanitize/fuzz/<t>/corpus (FUZZ_KEEP_CORPUS=1 keeps the previous run's
# corpus instead); the checked-in corpus never grows. Limits: -timeout=10
# (a hang), -rss_limit_mb=2048 (out of memory). Prints per target the
# executions, coverage (cov, ft: libFuzzer's final figures), corpus size,
# seconds and the result; the log and any crashing input stay in
# build-sanitize/fuzz/<t>/. Exits non-zero on any crash, hang or OOM.
# FUZZ_NO_BUILD=1 skips the build.
set -euo pipefail
cd "$(dirname "$0")/.."

targets_all=(obj ply off stl om meshcache scene shaderlog uniforms journal camerapath coursecode htmlshaders jsshaders)
mode=fuzz
runs=""
case "${1:-}" in
  --replay) mode=replay; shift ;;
  --make-seeds) mode=seeds; shift ;;
  --list) printf '%s\n' "${targets_all[@]}"; exit 0 ;;
  --runs) runs="${2:?--runs needs a number}"; shift 2 ;;
  -h|--help) sed -n '2,/^set -e/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
esac
target="${1:-all}"
seconds="${2:-60}"
if [ "$target" = all ]; then
  targets=("${targets_all[@]}")
else
  if [[ ! " ${targets_all[*]} " == *" $target "* ]]; then
    echo "fuzz: unknown target '$target' (targets: ${targets_all[*]})" >&2
    exit 2
  fi
  targets=("$target")
fi

build=build-sanitize
if [ "${FUZZ_NO_BUILD:-0}" != 1 ]; then
  if [ "$mode" = seeds ]; then
    bash scripts/build.sh --sanitize fuzz_make_seeds
  else
    bash scripts/build.sh --sanitize "${targets[@]/#/fuzz_}"
  fi
fi

if [ "$mode" = seeds ]; then
  exec "$build/tests/fuzz/fuzz_make_seeds" tests/fuzz/corpus tests/data
fi

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0:${LSAN_OPTIONS:-}"
limits=(-timeout=10 -rss_limit_mb=2048)

# What went wrong, from a libFuzzer log.
verdict() {
  local log="$1"
  if grep -q "ERROR: libFuzzer: timeout" "$log"; then echo "HANG (timeout)"
  elif grep -q "ERROR: libFuzzer: out-of-memory" "$log"; then echo "OUT OF MEMORY"
  elif grep -q "ERROR: LeakSanitizer" "$log"; then echo "LEAK"
  elif grep -q "ERROR: AddressSanitizer" "$log"; then echo "CRASH ($(grep -m1 -o 'ERROR: AddressSanitizer: [a-z-]*' "$log" | cut -d' ' -f3))"
  elif grep -q "runtime error:" "$log"; then echo "UNDEFINED BEHAVIOUR"
  elif grep -q "broken promise" "$log"; then echo "BROKEN PROMISE"
  elif grep -q "ERROR: libFuzzer: deadly signal" "$log"; then echo "CRASH (signal)"
  else echo "FAILED"
  fi
}

failed=0
if [ "$mode" = replay ]; then
  printf '%-10s %7s  %s\n' target inputs result
  for t in "${targets[@]}"; do
    dir="$build/fuzz/$t"
    mkdir -p "$dir"
    mapfile -t inputs < <(find "tests/fuzz/corpus/$t" "tests/data/fuzz/$t" -type f 2>/dev/null | sort)
    log="$dir/replay.log"
    if [ "${#inputs[@]}" -eq 0 ]; then
      printf '%-10s %7s  %s\n' "$t" 0 "no inputs"
      failed=1
      continue
    fi
    if "$build/tests/fuzz/fuzz_$t" "${limits[@]}" -artifact_prefix="$dir/" "${inputs[@]}" >"$log" 2>&1; then
      printf '%-10s %7s  %s\n' "$t" "${#inputs[@]}" ok
    else
      failed=1
      printf '%-10s %7s  %s: %s (log: %s)\n' "$t" "${#inputs[@]}" "$(verdict "$log")" \
        "$(grep -o 'Running: .*' "$log" | tail -n 1 | cut -d' ' -f2)" "$log"
    fi
  done
  exit "$failed"
fi

if [ -n "$runs" ]; then
  budget=(-runs="$runs")
  echo "fuzz: ${targets[*]}: $runs executions each"
else
  budget=(-max_total_time="$seconds")
  echo "fuzz: ${targets[*]}: $seconds s each"
fi
printf '%-10s %12s %7s %7s %18s %8s  %s\n' target executions cov ft corpus seconds result
for t in "${targets[@]}"; do
  dir="$build/fuzz/$t"
  mkdir -p "$dir/artifacts"
  if [ "${FUZZ_KEEP_CORPUS:-0}" != 1 ] || [ ! -d "$dir/corpus" ]; then
    rm -rf "$dir/corpus"
    cp -r "tests/fuzz/corpus/$t" "$dir/corpus"
  fi
  log="$dir/fuzz.log"
  start=$(date +%s)
  status=0
  "$build/tests/fuzz/fuzz_$t" "${limits[@]}" "${budget[@]}" -print_final_stats=1 \
    -artifact_prefix="$dir/artifacts/" "$dir/corpus" >"$log" 2>&1 || status=$?
  elapsed=$(( $(date +%s) - start ))
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  last=$(grep -E '^#[0-9]+' "$log" | grep 'cov:' | tail -n 1 || true)
  [ -n "$execs" ] || execs=$(sed -E 's/^#([0-9]+).*/\1/' <<<"$last")
  cov=$(grep -o 'cov: [0-9]*' <<<"$last" | cut -d' ' -f2 || true)
  ft=$(grep -o 'ft: [0-9]*' <<<"$last" | cut -d' ' -f2 || true)
  corp=$(grep -o 'corp: [0-9]*/[0-9]*[a-zA-Z]*' <<<"$last" | cut -d' ' -f2 || true)
  if [ "$status" -eq 0 ]; then
    result=ok
  else
    failed=1
    result="$(verdict "$log"): $(grep -o 'Test unit written to .*' "$log" | tail -n 1 | cut -d' ' -f5-) (log: $log)"
  fi
  printf '%-10s %12s %7s %7s %18s %8s  %s\n' "$t" "${execs:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$elapsed" "$result"
done
exit "$failed"
