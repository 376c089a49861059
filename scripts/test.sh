#!/usr/bin/env bash
# Installs, builds, and runs the whole test suite (CTest) under a virtual X
# server: the GL and UI tests need OpenGL, which Mesa provides inside Xvfb.
# Extra arguments go to ctest (e.g. -R render -V).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
export PHONGLAB_TEST_ARTIFACTS="$PWD/build/test-artifacts"
xvfb-run -a -s "-screen 0 1280x1024x24" \
  ctest --test-dir build --output-on-failure --parallel 2 --timeout 600 "$@"

# The render-versus-reference figures, which passing tests do not show.
log=build/Testing/Temporary/LastTest.log
if [ -f "$log" ] && grep -q "PSNR" "$log"; then
  echo
  echo "GPU render versus CPU reference (from $log):"
  grep -h "QINFO.*PSNR" "$log" | sed -E 's/^QINFO *: *[A-Za-z]+::/  /'
fi
