#pragma once
#include <QString>
#include <QStringList>
#include <map>
#include <vector>

namespace phonglab::cli {

// A teacher's folder of submissions, as `phonglab grade` reads it: each
// subfolder is one student's, holding that student's vertex and/or fragment
// shader under any file names. A stage is known by its file's suffix
// (.vert .vs .vsh for the vertex stage, .frag .fs .fsh for the fragment
// stage) and, for .glsl, by whether the text writes gl_Position. Files are
// looked for in the subfolder and the folders below it (an unpacked archive
// often adds one level). A subfolder with pages or scripts (.html, .js), or
// with more than one file for a stage, is read as a WebGL project
// (core/project): each program in it that lights is a submission of its
// own, by the same name, with its program's name.

struct Submission {
    QString name;     // the subfolder's name
    QString folder;   // absolute
    QString vertex;   // absolute; empty: the method's shipped vertex shader
    QString fragment; // absolute; empty: the method's shipped fragment shader
    QString error;    // why it cannot be checked (two files for one stage, no shader at all)
    // A WebGL project's program: its name; the stages are then
    // "FILE#KEY" locators into the project's pages, scripts or files.
    QString program;
    QStringList notes; // what the project says beside (unlit programs left out)
    // From a course platform's names (ClassStaging): Moodle's full name and
    // participant number; empty elsewhere.
    QString student;
    QString participant;
    // grade --pages: the values the page gave the uniforms no meaning binds
    // (a mode switch), handed to its checks as --bind NAME=VALUE.
    std::map<QString, std::vector<double>> pageConstants;
};

struct ClassFolder {
    // By name, then program, in code-point order (the same on every machine).
    std::vector<Submission> submissions;
    QString error; // the folder cannot be read, or has no subfolder
};

ClassFolder readClassFolder(const QString &path);

} // namespace phonglab::cli
