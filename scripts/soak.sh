#!/usr/bin/env bash
# Soak: one app process under Xvfb through 1,000 live edits (good and broken
# alternating), 100 scene reloads and 100 mesh loads (each through the import
# child). Prints resident memory after warm-up and at the end (aim: growth
# under 10 %) and the live GL programs, buffers and textures (aim: none
# added). Exit 0 when both aims hold. Takes a few minutes.
#   scripts/soak.sh [--edits N] [--reloads N] [--loads N]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
export PHONGLAB_EXE="$PWD/build/app/phonglab"
exec xvfb-run -a -s "-screen 0 1280x1024x24" build/tests/tools/soak "$@"
