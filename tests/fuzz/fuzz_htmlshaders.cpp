// libFuzzer target: see FuzzEntry.h (runHtmlShaders) and scripts/fuzz.sh.
#include "FuzzEntry.h"

PHONGLAB_FUZZ_TARGET("htmlshaders")
