#pragma once
#include <QByteArray>
#include <QString>

#include <vector>

namespace phonglab {

// Values a shader reads that GLSL leaves undefined, which no one picture can
// be trusted to show: a driver may read them as 0 (the image is then right
// there and wrong on the student's own browser or GPU) or as whatever was
// there. Found by reading the text alone (GLSL ES 1.00, 3.00 and desktop
// GLSL), in the order a function runs its statements; a warning, never a
// verdict.
struct LintFinding {
    int line = 0;   // 1-based, in the code as given
    int column = 0; // 1-based, in characters, where the bad read starts
    QString variable;
    enum class Kind {
        ReadBeforeSet,           // a local declared without a value, read before any write
        OutputReadBeforeWritten, // a global `out` read in main() before any write
    } kind = Kind::ReadBeforeSet;
    QString message; // one translated sentence
};

// Each variable at most once, at its first bad read, in the order of the text.
// Only what is certain is flagged: a write on some paths (one branch of an if,
// a loop body), a macro that names the variable, or a call of a function the
// text does not show all count as a write, since a false warning on a correct
// shader costs a student more than a missed one.
std::vector<LintFinding> lintShader(const QByteArray &code);

} // namespace phonglab
