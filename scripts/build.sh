#!/usr/bin/env bash
# Installs what is missing, then configures and builds PhongLab.
#   scripts/build.sh                        ./build (the compiler cmake finds, g++ on Debian)
#   scripts/build.sh --app                  ./build, the phonglab program alone (scripts/run.sh)
#   scripts/build.sh --sanitize [TARGET...] ./build-sanitize: clang 14, ASan + UBSan
#       everywhere, libFuzzer targets added (PHONGLAB_FUZZ=ON, see
#       cmake/Sanitizers.cmake); only TARGETs (and what they need) when given.
#       scripts/test.sh --sanitize and scripts/fuzz.sh build here.
# Uses ccache when it is installed (scripts/setup.sh installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

launcher=()
if command -v ccache >/dev/null; then
  # The sloppiness ccache needs to cache files compiled with a precompiled
  # header (cmake/BuildSpeed.cmake); without it every such call is
  # "uncacheable".
  launcher=("-DCMAKE_CXX_COMPILER_LAUNCHER=env;CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime;ccache")
fi

if [ "${1:-}" = "--sanitize" ]; then
  shift
  targets=()
  for t in "$@"; do targets+=(--target "$t"); done
  # -O1 and line tables only: what libFuzzer recommends, with readable
  # stack traces and no full debug info to build (CI builds this too).
  cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
    -DCMAKE_CXX_COMPILER=clang++-14 -DPHONGLAB_FUZZ=ON -DPHONGLAB_SANITIZE=address,undefined \
    "${launcher[@]}" >/dev/null
  cmake --build build-sanitize --parallel "$(nproc)" "${targets[@]}"
  exit 0
fi

targets=()
if [ "${1:-}" = "--app" ]; then
  targets=(--target phonglab)
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}"
cmake --build build --parallel "$(nproc)" "${targets[@]}"
