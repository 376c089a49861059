#pragma once
#include "BenchResult.h"
#include "ErrorBudget.h"

#include <QString>
#include <vector>

namespace phonglab {

// The per-object fit: each object of a scene gets its own method and
// detail, the cheapest combination whose whole image stays within the
// budget. It works on the single-object rows of one scene (BenchRow::object:
// each object drawn alone for its time, its error measured over its own
// pixels), so the image's error is known from the parts: the max error is
// the largest of the objects', the squared errors add up over the pixels.
// Its time is the sum of the objects' own times (each includes the frame's
// fixed cost, so the sum errs high); the bench then draws the chosen
// combination once to measure it whole.

struct ObjectChoice {
    QString object;
    int row = -1;     // index into the rows given; -1 when nothing fits for this object
    int fastest = -1; // its fastest row, fitting or not
};

struct ObjectFit {
    std::vector<ObjectChoice> choices; // per object, in order of first appearance
    bool fits = false;                 // every object has a choice and the whole is within budget
    double frameMs = 0.0;              // sum of the chosen rows' frame times
    double baselineMs = 0.0; // sum of the objects' full-detail Phong times (0: not measured)
    int maxError = 0;        // of the combination
    double psnr = 0.0;       // of the combination, dB
    // The object that limits the saving: the one whose choice costs the
    // most time above its own fastest row; empty when every object is at
    // its fastest.
    QString limiting;
    QString summary; // one line for people
};

// Combined error of one row per object (indices into rows).
struct CombinedError {
    int maxError = 0;
    double psnr = 0.0; // +inf when exact; 0 when no pixel was compared
};
CombinedError combineObjectErrors(const std::vector<BenchRow> &rows,
                                  const std::vector<int> &chosen);

// `rows`: one scene's rows at its own lights; the whole-scene rows among them
// are ignored. Never returns a combination the budget refuses.
ObjectFit fitObjects(const std::vector<BenchRow> &rows, const ErrorBudget &budget);

} // namespace phonglab
