#!/usr/bin/env bash
# Installs, builds, and launches PhongLab on its default scene (or on the
# scene file given as an argument). Without a display it starts a virtual
# X server so the app still comes up (useful over ssh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh --app # the program alone: tests and benchmarks are test.sh's
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  echo "run: no display found; starting the app under a virtual X server (xvfb-run)"
  exec xvfb-run -a ./build/app/phonglab "$@"
fi
exec ./build/app/phonglab "$@"
