// libFuzzer target: see FuzzEntry.h (runMeshCache) and scripts/fuzz.sh.
#include "FuzzEntry.h"

PHONGLAB_FUZZ_TARGET("meshcache")
