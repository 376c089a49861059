#pragma once
#include <QtGlobal>

namespace phonglab::bench {

// One edit's figures, in milliseconds.
struct EditSample {
    double totalMs = 0;   // edit (after the debounce) to the first finished frame
    double compileMs = 0; // both stages
    double linkMs = 0;
    // The warm-up draw off the GUI thread; in the app, with the trial and,
    // when it presents it there (frameFromLoan), the first frame too.
    double warmMs = 0;
    double frameMs = 0;         // the first frame drawn on the GUI thread (0: none)
    bool frameFromLoan = false; // presented by the trial in the lent context
    double otherMs = 0;         // the rest: queues, thread hops, adopting the program
    double stallMs = 0;         // the longest the GUI thread did not get to its event loop
    // ... from the edit until the live check of the new program has its
    // verdict (it draws the scene again on the GUI thread after the frame)
    double stallUntilCheckedMs = 0;
    double steadyMs = 0; // a further frame with the same program, for comparison
};

inline double ms(qint64 ns)
{
    return double(ns) / 1e6;
}

} // namespace phonglab::bench
