#pragma once
#include <QString>

namespace phonglab {

// What a check says of a program: one word for `check`, `grade` and the
// window alike. `check` and the window give the first three; a row of
// `grade` may also be Timeout or Crash, what its child did instead of
// answering.
enum class Verdict {
    Pass,
    Fail,
    Error,   // no verdict on the lighting: a compile error, an unbound name, bad input
    Timeout, // grade's child ran past --timeout
    Crash    // grade's child died, or used more memory than allowed
};

// "pass", "fail", "error", "timeout", "crash": the word the JSON, the CSV
// and the course platform's files carry, whatever language the run speaks.
QString verdictName(Verdict verdict);

} // namespace phonglab
