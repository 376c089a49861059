#pragma once
#include "SubmissionArchive.h"

#include <QHash>
#include <QString>

namespace phonglab::cli {

// What `grade` is handed, made into a folder of one subfolder per
// submission:
// - a folder as it is (plain, or GitHub Classroom's `assignment-user/`);
// - a .zip or .tar.gz (a course platform's "download all"), unpacked into
//   the out folder's `unpacked/`;
// - Moodle's flat layout (`Full Name_12345_assignsubmission_file_index.html`)
//   regrouped there into one folder per student, named as Moodle names its
//   folders (`Full Name_12345_assignsubmission_file_`);
// - a student's own archive inside their folder, unpacked beside it
//   (`hand-in.zip.unpacked/`), once: an archive in that is not opened.
// A teacher's folder is never written into: where anything must change, the
// class is copied into `unpacked/` first (plain files only, never a link).

struct SubmissionOrigin {
    QString student;     // Moodle's full name; empty elsewhere
    QString participant; // Moodle's participant number
};

struct StagedClass {
    QString root;                             // whose subfolders are the submissions
    QHash<QString, SubmissionOrigin> origins; // by subfolder name
    QHash<QString, QString> refused;          // by subfolder name: an archive refused, why
    QString error;                            // nothing could be read
};

StagedClass stageClass(const QString &submissions, const QString &outFolder,
                       const ArchiveLimits &limits = {});

// Moodle's name of a submission's folder or file, read: the student's full
// name, the participant number, the plugin ("file", "onlinetext") and, for
// a flat file, the file's own name. Nothing where the name is not Moodle's.
struct MoodleName {
    QString student;
    QString participant;
    QString plugin;
    QString rest;
    QString folder() const; // "Full Name_12345_assignsubmission_file_"
};
std::optional<MoodleName> moodleName(const QString &name);

} // namespace phonglab::cli
