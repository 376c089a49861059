#pragma once
#include "GradeRows.h"

#include <QString>

namespace phonglab::cli {

// report.html: one page a teacher opens in a browser, its images in the
// images/ folder beside it. A summary first (passes per scene, the most
// common mistakes, as charts), then a row per student and scene: their
// image, the exact one and the heatmap side by side, the diagnosis, the
// offending lines in context, and the command that opens the submission in
// the window. Rows sort by student, verdict or PSNR (a click on the header,
// or #sort=verdict in the address). No script or style from elsewhere:
// the page works offline. Everything a student wrote is escaped for HTML,
// and the commands for a POSIX shell.
QString gradeReportHtml(const GradeResults &results);

// 'text' for a POSIX shell: unquoted where that is safe.
QString shellQuoted(const QString &text);

} // namespace phonglab::cli
