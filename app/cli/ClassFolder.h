#pragma once
#include <QString>
#include <vector>

namespace phonglab::cli {

// A teacher's folder of submissions, as `phonglab grade` reads it: each
// subfolder is one student's, holding that student's vertex and/or fragment
// shader under any file names. A stage is known by its file's suffix
// (.vert .vs .vsh for the vertex stage, .frag .fs .fsh for the fragment
// stage) and, for .glsl, by whether the text writes gl_Position. Files are
// looked for in the subfolder and the folders below it (an unpacked archive
// often adds one level).

struct Submission {
    QString name;     // the subfolder's name
    QString folder;   // absolute
    QString vertex;   // absolute; empty: the method's shipped vertex shader
    QString fragment; // absolute; empty: the method's shipped fragment shader
    QString error;    // why it cannot be checked (two files for one stage, no shader at all)
};

struct ClassFolder {
    std::vector<Submission> submissions; // by name, in code-point order (the same on every machine)
    QString error;                       // the folder cannot be read, or has no subfolder
};

ClassFolder readClassFolder(const QString &path);

} // namespace phonglab::cli
