#!/usr/bin/env bash
# Regenerates the pictures in docs/images/ (README, first-five-minutes) with
# the app's own code, under a virtual X server: in English, and in German
# for the pages in docs/de/ (docs/images/de/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
QT_QPA_PLATFORM=xcb xvfb-run -a -s "-screen 0 1920x1080x24" build/tests/tools/make_screenshots docs/images
env -u LANGUAGE -u LC_ALL -u LC_MESSAGES LANG=de_DE.UTF-8 QT_QPA_PLATFORM=xcb \
  xvfb-run -a -s "-screen 0 1920x1080x24" build/tests/tools/make_screenshots docs/images/de
