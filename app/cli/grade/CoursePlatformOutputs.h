#pragma once
#include "GradeRows.h"

#include "core/support/Result.h"

#include <QByteArray>
#include <QString>

namespace phonglab::cli {

// What goes back to a course platform, Moodle first: a grade
// and a comment per participant for its offline grading worksheet, and a
// zip of feedback pages for its "upload multiple feedback files in a zip".

// --points: what each verdict is worth, summed over a student's rows (each
// scene, and each program where a project has several).
struct GradePoints {
    double pass = 1.0;
    double fail = 0.0;
    double error = 0.0;
    double timeout = 0.0;
    double crash = 0.0;
    double of(Verdict verdict) const;
};
// "pass=2,fail=0.5"; the verdicts not named keep their default. An error
// names what is wrong.
Result<GradePoints> parseGradePoints(const QString &text);

// moodle-grades.csv: "Identifier","Full name","Grade","Feedback comments",
// a record per Moodle participant ("Participant 12345"), every field
// quoted; empty when no submission came from Moodle.
QByteArray moodleGradesCsv(const GradeResults &results, const GradePoints &points);
// The comment: a short sentence per row, in the run's language.
QString feedbackComment(const GradeResults &results, int submissionFolderIndex);

// feedback.zip: a folder per Moodle participant, named as in the download,
// holding feedback.html (that student's rows alone: grade's report made of
// them) and the images it shows. Nothing when no submission came from Moodle.
Result<> writeFeedbackZip(const GradeResults &results, const QString &zipPath);

} // namespace phonglab::cli
