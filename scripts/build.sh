#!/usr/bin/env bash
# Installs what is missing, then configures and builds PhongLab.
#   scripts/build.sh                        ./build (the compiler cmake finds, g++ on Debian)
#   scripts/build.sh --app                  ./build, the phonglab program alone (scripts/run.sh)
#   scripts/build.sh --sanitize [TARGET...] ./build-sanitize: clang 14, ASan + UBSan
#       everywhere, libFuzzer targets added (PHONGLAB_FUZZ=ON, see
#       cmake/Sanitizers.cmake); only TARGETs (and what they need) when given.
#       scripts/test.sh --sanitize and scripts/fuzz.sh build here.
#   scripts/build.sh --thread [TARGET...]   ./build-tsan: g++ 12, ThreadSanitizer
#       (scripts/test.sh --thread).
# Asserts are live in every build; the project's own code builds with -Werror.
# Uses ccache when it is installed (scripts/setup.sh installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

# Every build is a preset of CMakePresets.json: plain (./build), sanitize
# (./build-sanitize), thread (./build-tsan). ccache, when installed, is
# chosen by CMakeLists.txt itself.
if [ "${1:-}" = "--sanitize" ] || [ "${1:-}" = "--thread" ]; then
  preset=sanitize
  [ "$1" = "--thread" ] && preset=thread
  shift
  targets=()
  for t in "$@"; do targets+=(--target "$t"); done
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" --parallel "$(nproc)" "${targets[@]}"
  exit 0
fi

cmake --preset plain
if [ "${1:-}" = "--app" ]; then
  cmake --build --preset app --parallel "$(nproc)"
else
  cmake --build --preset plain --parallel "$(nproc)"
fi
