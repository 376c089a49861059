// libFuzzer target: see FuzzEntry.h (runJournal) and scripts/fuzz.sh.
#include "FuzzEntry.h"

PHONGLAB_FUZZ_TARGET("journal")
