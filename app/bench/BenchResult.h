#pragma once
#include "core/support/Result.h"
#include <QString>
#include <QStringList>

#include <cmath>
#include <limits>
#include <vector>

namespace phonglab {

// One measured configuration of `phonglab bench`: a scene drawn with one
// shading method, at one level of detail, under one light setup. Speed is
// wall time; accuracy is the 8-bit render against the CPU double-precision
// reference of the Phong equation (the exact answer every method
// approximates), away from silhouettes.
//
// One row is one line of results.csv; the column names (benchCsvColumns()) are an
// interface other tools rely on: add columns at the end, never rename.
struct BenchRow {
    QString scene;            // scene name (file base name, e.g. "default")
    QString method;           // shadingName(): "flat", "gouraud", "faceted", "phong", "blinn-phong"
    double detail = 1.0;      // requested fraction of the full triangle count (1 = full)
    qint64 triangles = 0;     // triangles drawn per frame at this detail
    int lights = 0;           // number of point lights
    bool sceneLights = false; // true: exactly the scene's own lights (the fit uses these rows)

    double frameMs = 0;     // median wall time of render + glFinish, ms
    double frameMsP90 = 0;  // 90th percentile of the same
    double cpuSubmitMs = 0; // median time until render() returned (CPU submission), ms
    double gpuMs = std::numeric_limits<
        double>::quiet_NaN(); // GL_TIME_ELAPSED median; NaN where not trusted (llvmpipe)
    int frames = 0;           // frames timed after warm-up

    double psnr = 0;         // dB; +inf when identical
    double rmse = 0;         // 8-bit steps
    int maxError = 0;        // 8-bit steps, 0..255
    double specularPsnr = 0; // the same three inside the specular highlight alone
    double specularRmse = 0;
    int specularMaxError = 0;
    qint64 specularPixels = 0; // pixels in the highlight mask (0: no highlight visible)
    qint64 pixelsCompared = 0;
    qint64 coverageErrors =
        0; // pixels outside the silhouette band covered in one image and not the other
    // Empty: the whole scene drawn with this method and detail. Otherwise one
    // object of it ("0: tree.obj"), drawn alone for the time and measured
    // over its own pixels for the error: the rows of the per-object fit
    // (ObjectFit.h), at the scene's own lights.
    QString object;

    // The full-detail Phong row of a scene and light setup is the baseline
    // the savings are measured against.
    bool isBaseline() const
    {
        return method == QLatin1String("phong") && detail >= 1.0 && object.isEmpty();
    }
    bool isWholeScene() const { return object.isEmpty(); }
};

// A detail fraction for people: "100 %", "25 %", "12.5 %", "1.56 %".
QString detailPercent(double detail);

// One CSV field as written: quoted (RFC 4180) when it holds a comma, a
// quote, a line break or edge spaces. Shared by every CSV the bench writes.
QString csvField(const QString &field);

// The results.csv header, in column order.
QStringList benchCsvColumns();

// results.csv: a header line, then one line per row. Numbers are written
// with enough digits to read back exactly; NaN as an empty field, +inf as "inf".
QString benchRowsToCsv(const std::vector<BenchRow> &rows);
// Parses what benchRowsToCsv() wrote (columns found by name, so files with
// more columns still read): the rows, or a failure naming `sourceName`
// (e.g. the file's path) and the line: "<sourceName> line 7: frame_ms is
// not a number: 'abc'".
Result<std::vector<BenchRow>> benchRowsFromCsv(
    const QString &text, const QString &sourceName = QStringLiteral("results.csv"));

} // namespace phonglab
