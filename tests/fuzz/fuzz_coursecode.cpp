// libFuzzer target: see FuzzEntry.h (runCourseCode) and scripts/fuzz.sh.
#include "FuzzEntry.h"

PHONGLAB_FUZZ_TARGET("coursecode")
