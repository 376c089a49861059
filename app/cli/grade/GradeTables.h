#pragma once
#include "GradeRows.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>

namespace phonglab::cli {

// grade's outputs for scripts and for the terminal.

// grades.csv: a header and one record per row, columns submission, scene,
// verdict, psnr_db, max_error, bad_fraction, key, also, file, line,
// equation, bindings, seconds, mistakes, program, student, participant,
// page_fidelity, page_own_scene, page_javascript, page_error (an interface: never renamed
// or reordered; new columns go last).
// The same results give the same bytes, apart from `seconds`. Text a
// student chose (folder and file names) is quoted for CSV, and a cell that
// a spreadsheet would run as a formula (=, +, -, @ first) gets a leading '.
QByteArray gradesCsv(const GradeResults &results);

// grades.json: {"scenes": [...], "rows": [{submission, scene, seconds, and
// the check's --json keys, its verdict the grade's, and with --pages
// "page", check --page's}]}.
QJsonObject gradesJson(const GradeResults &results);

// The table on stdout: a line per submission × scene, the student named on
// their first line.
QString gradesTable(const GradeResults &results);

} // namespace phonglab::cli
