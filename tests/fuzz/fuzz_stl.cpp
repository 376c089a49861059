// libFuzzer target: see FuzzEntry.h (runMesh) and scripts/fuzz.sh.
#include "FuzzEntry.h"

PHONGLAB_FUZZ_TARGET("stl")
