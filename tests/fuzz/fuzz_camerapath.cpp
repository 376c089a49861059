// libFuzzer target: see FuzzEntry.h (runScene) and scripts/fuzz.sh.
#include "FuzzEntry.h"

PHONGLAB_FUZZ_TARGET("camerapath")
