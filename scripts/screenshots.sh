#!/usr/bin/env bash
# Regenerates the pictures in docs/images/ (README, first-five-minutes) with
# the app's own code, under a virtual X server.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
QT_QPA_PLATFORM=xcb xvfb-run -a -s "-screen 0 1920x1080x24" build/tests/tools/make_screenshots docs/images
