#pragma once
#include "cli/check/GradedChild.h"

#include <QFile>
#include <QHash>
#include <QString>

namespace phonglab::cli {

// What a grade run has finished, row by row, so that a run stopped by
// Ctrl-C or a crash loses nothing: each child's end is
// appended to DIR/grades.partial.jsonl as it comes, flushed, and `grade
// --resume` checks those rows again from it instead of drawing them again.
// The checking is deterministic, so the resumed run's tables are the
// uninterrupted run's, apart from `seconds`. The first line is the run's
// fingerprint (scenes, settings, submissions and their files): a journal of
// another run is not used. It is removed once the run has written its tables.
class GradeJournal
{
public:
    // `fingerprint`: what makes two runs the same run.
    GradeJournal(const QString &outFolder, const QByteArray &fingerprint);

    // The rows a stopped run of this fingerprint finished, by row key (empty
    // if there is no such journal); then starts the journal afresh with
    // them, so that a second stop loses nothing either.
    QHash<QString, GradedChildEnd> resume();
    // Starts a new journal (a run without --resume).
    void start();
    void record(const QString &rowKey, const GradedChildEnd &end);
    void finish(); // the tables are written: the journal goes

private:
    void writeLine(const QByteArray &line);

    QString m_path;
    QByteArray m_fingerprint;
    QFile m_file;
};

} // namespace phonglab::cli
