#pragma once
#include "ErrorBudget.h"
#include "core/support/Result.h"
#include "core/view/CameraPath.h"

#include <QSize>
#include <QString>
#include <functional>
#include <memory>
#include <vector>

namespace phonglab {

class OffscreenRenderer;

// `phonglab bench --path`: a scene drawn along a scripted camera path with
// everything that models no more than the view needs (every object at
// "detail": "auto", lights that cannot be seen left out), each frame timed
// and compared with the exact answer (the CPU reference of the Phong
// equation on the full meshes, all lights), and timed against the same
// frame at full detail with every light.

struct PathOptions {
    QSize size{400, 300};
    int warmupFrames = 2;
    int frames = 10;                     // timed frames per path frame (median)
    int bandPx = 2;                      // silhouette band left out of the error
    ErrorBudget budget;                  // what counts as over budget
    double detailPixels = 0.5;           // Renderer::Options::detailPixels
    QString imageDir;                    // when set: a render | reference | error picture per frame
    int pathFrames = kDefaultPathFrames; // frames of an orbit or a dolly (a file gives its own)
};

struct PathFrame {
    int index = 0;
    glm::dvec3 eye{0.0};
    double distance = 0.0; // eye to target
    int maxError = 0;      // 8-bit steps, outside the silhouette band
    double psnr = 0.0;
    double rmse = 0.0;
    qint64 pixelsCompared = 0;
    bool overBudget = false;
    int fullMaxError = 0;        // the full-detail frame with every light, the same way
    bool fullOverBudget = false; // over budget at full detail too: the method, not the model
    double frameMs = 0.0;        // auto detail, lights left out
    double fullFrameMs = 0.0;    // full detail, every light
    qint64 triangles = 0;
    qint64 fullTriangles = 0;
    int lightsLeftOut = 0;
    QString levels; // per object, the level drawn: "3/7 2/6"
};

struct PathRun {
    QString scene; // base name
    QString path;  // CameraPath::name
    std::vector<PathFrame> frames;

    int overBudget() const;
    int fullOverBudget() const; // frames over budget even at full detail
    qint64 triangles() const;   // summed over the frames
    qint64 fullTriangles() const;
    double frameMs() const;
    double fullFrameMs() const;
};

// Called after each frame; returns false to cancel.
using PathProgressFn = std::function<bool(int done, int total, const PathFrame &frame)>;

class PathBench
{
public:
    PathBench();
    ~PathBench();
    Result<> initialize(); // makes the two offscreen contexts
    QString glRendererName() const;

    // `pathSpec`: "orbit", "dolly", or a keyframe file (CameraPath.h).
    Result<PathRun> run(const QString &scenePath, const QString &pathSpec,
                        const PathOptions &options, const PathProgressFn &progress = {});

private:
    std::unique_ptr<OffscreenRenderer> m_auto; // auto detail, lights left out
    std::unique_ptr<OffscreenRenderer> m_full; // full detail, every light
};

// path.csv: a header line, then one line per frame of every run.
QString pathRunsToCsv(const std::vector<PathRun> &runs);

} // namespace phonglab
