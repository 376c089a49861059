// libFuzzer target: see FuzzEntry.h (runUniforms) and scripts/fuzz.sh.
#include "FuzzEntry.h"

PHONGLAB_FUZZ_TARGET("uniforms")
