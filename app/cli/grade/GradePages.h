#pragma once
#include "GradeRows.h"
#include "cli/page/PageOptions.h"

namespace phonglab::cli {

// grade --pages: each submission's page run in headless Chromium
// (`jobs` at once: each run is a browser of its own), then checked here
// one by one (core/page: fidelity, the JavaScript half). What it found goes
// to results.pages; its capture and frames to the out folder's
// pages/<submission>/. A submission whose page drew its program gets the
// page's values (a mode switch: --bind NAME=VALUE for its checks) and,
// where the page rewrote the shader before compiling, the stages as
// compiled. A progress line on stderr; a project without a page is left
// as it is.
void runSubmissionPages(GradeResults &results, const PageRequest &request, int jobs);

} // namespace phonglab::cli
