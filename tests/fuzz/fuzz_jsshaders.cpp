// libFuzzer target: see FuzzEntry.h (runJsShaders) and scripts/fuzz.sh.
#include "FuzzEntry.h"

PHONGLAB_FUZZ_TARGET("jsshaders")
