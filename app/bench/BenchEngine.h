#pragma once
#include "BenchOptions.h"
#include "BenchResult.h"
#include "ObjectFit.h"
#include "core/reference/ReferenceImage.h"
#include "core/scene/Scene.h"
#include "core/support/Result.h"

#include <QImage>
#include <QString>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace phonglab {

class OffscreenRenderer;
struct MeshData;

// The per-object fit of one scene and the combination it chose, drawn
// whole: its real time and error (nullopt when nothing fitted).
struct ObjectFitCheck {
    QString scene;
    ObjectFit fit;
    std::optional<BenchRow> measured;
};

// Where a bench run is; the callback returns false to cancel.
struct BenchProgress {
    int done = 0;  // configurations measured so far
    int total = 0; // configurations in the whole run
    QString stage; // "default: reference, 4 lights" / "default: phong, detail 25 %, 4 lights"
    // The rows this step measured: the whole scene's, then at the scene's
    // own lights one per object (drawn alone); empty for a step that
    // measured none.
    std::span<const BenchRow> rows;
};
using BenchProgressFn = std::function<bool(const BenchProgress &)>;

// The speed-against-accuracy sweep behind `phonglab bench` and the
// Performance dock: every scene × detail × method × light setup of the
// options, timed on the GPU (glFinish-bounded wall time, CPU submission,
// GL_TIME_ELAPSED where trusted) and compared with the CPU double-precision
// reference of the Phong equation (analytic surfaces for builtins, the
// full-resolution mesh ray-cast with interpolated normals otherwise).
//
// Needs a QGuiApplication and makes its own offscreen context; run it on the
// thread that owns the application.
class BenchEngine
{
public:
    BenchEngine();
    ~BenchEngine();

    // A failure when no GL context can be made.
    Result<> initialize();
    QString glRendererName() const;

    // With options.objectFitBudget: per scene of two objects or more, the
    // per-object fit of the last run and the chosen combination measured.
    const std::vector<ObjectFitCheck> &objectFits() const { return m_objectFits; }

    // Appends one row per configuration to *rows. A failure when a
    // scene cannot be loaded or a shader does not build, or "cancelled".
    Result<> run(const BenchOptions &options, std::vector<BenchRow> *rows,
                 const BenchProgressFn &progress = {});

private:
    struct SceneRun;
    Result<> runScene(const BenchOptions &options, const QString &path, SceneRun &state,
                      std::vector<BenchRow> *rows, const BenchProgressFn &progress);
    Result<> measureDetail(const BenchOptions &options, SceneRun &state, double detail,
                           std::vector<BenchRow> *rows, const BenchProgressFn &progress);
    BenchRow measure(const BenchOptions &options, SceneRun &state, std::size_t setup,
                     ShadingMethod method, double detail);
    BenchRow measureFrame(const BenchOptions &options, SceneRun &state, std::size_t setup,
                          const Scene &scene, const QString &method, double detail);
    void measureObjects(const BenchOptions &options, SceneRun &state, std::size_t setup,
                        std::vector<BenchRow> *rows);
    Result<> checkObjectFit(const BenchOptions &options, SceneRun &state,
                            const std::vector<BenchRow> &rows, std::size_t firstRow);

    std::unique_ptr<OffscreenRenderer> m_offscreen;
    std::vector<ObjectFitCheck> m_objectFits;
    int m_done = 0;
    int m_total = 0;
};

// Configurations a run of `options` over `sceneLightCounts` (each scene's
// own enabled light count) measures, for progress totals.
int benchConfigurationCount(const BenchOptions &options, const std::vector<int> &sceneLightCounts);

// The light counts measured for a scene with `sceneLights` enabled lights:
// the options' counts plus the scene's own, ascending, each once.
std::vector<int> benchLightCounts(const BenchOptions &options, int sceneLights);

} // namespace phonglab
