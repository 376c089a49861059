// libFuzzer target: see FuzzEntry.h (runShaderLog) and scripts/fuzz.sh.
#include "FuzzEntry.h"

PHONGLAB_FUZZ_TARGET("shaderlog")
