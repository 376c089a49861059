#pragma once
#include "BenchResult.h"

#include <QString>
#include <optional>
#include <vector>

namespace phonglab {

// How far from the exact answer a scene may be drawn ("model no more than a
// scene needs"). Measured away from silhouettes (the bench's 2 px band).
struct ErrorBudget {
    enum class Kind {
        MaxError,
        Psnr
    };
    Kind kind = Kind::MaxError;
    int maxError = 2;      // Kind::MaxError: largest allowed error, 8-bit steps
    double minPsnr = 40.0; // Kind::Psnr: smallest allowed PSNR, dB

    bool accepts(const BenchRow &row) const;
    // The same for an error measured elsewhere (a frame of a camera path).
    bool accepts(int maxError, double psnr) const;
    // What each of the two reductions of the model (lights left out,
    // LightBound.h; coarser levels of detail, normalErrorBound()) may change
    // a pixel by: a quarter of the budget each (linear intensity), half of
    // it left for the method's own error and the rounding to 8 bits.
    double reductionAllowance() const;
    // "max error ≤ 2/255" or "PSNR ≥ 40 dB"
    QString describe() const;
    // "2" / "max:2" → MaxError 2; "psnr:40" / "40dB" → Psnr 40. nullopt on anything else.
    static std::optional<ErrorBudget> parse(const QString &text);
};

// What fitToBudget() chose for one scene and light setup.
struct BudgetFit {
    int chosen = -1;           // index into the rows given, -1 when nothing meets the budget
    int baseline = -1;         // the full-detail Phong row, -1 if it was not measured
    qint64 trianglesSaved = 0; // baseline.triangles - chosen.triangles
    double msSaved = 0;        // baseline.frameMs - chosen.frameMs
    QString summary;           // one line for people: what was chosen and what it saves
};

// Among `rows` (one scene, one light setup), the cheapest that meets the
// budget: least frame time, where times within kTimeTieFraction of the
// fastest accepted one count as equal (frame times are noisy); among those
// the fewest triangles win, then the lower error (equally cheap, so the
// accuracy is free), then the cheaper method (flat < gouraud < blinn-phong
// < phong). Never returns a row the budget refuses. Rows of single objects
// (BenchRow::object) are left out: fitObjects() (ObjectFit.h) takes those.
inline constexpr double kTimeTieFraction = 0.05;
BudgetFit fitToBudget(const std::vector<BenchRow> &rows, const ErrorBudget &budget);

} // namespace phonglab
