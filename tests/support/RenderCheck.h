#pragma once
#include "core/reference/AnalyticRaycaster.h"
#include "core/reference/ImageMetrics.h"
#include "core/scene/MeshData.h"
#include "core/scene/Scene.h"
#include "render/program/BuildReport.h"
#include "render/program/ShaderSource.h"

#include <QHash>
#include <QImage>
#include <QString>
#include <memory>
#include <optional>

namespace phonglab::test {

// The bound a correct GPU render of an analytic builtin must meet against the
// double-precision ray-cast reference, outside a thin silhouette band (where
// the tessellated outline and the true outline cover different pixels).
inline constexpr double kMinPsnrDb = 50.0;
inline constexpr int kMaxErrorSteps = 3; // in 8-bit steps, per channel
inline constexpr int kSilhouetteBandPx = 2;
inline constexpr int kTestImageSide = 256;

struct RenderCheck {
    RgbImage gpu;
    RgbImage reference;
    ReferenceImage referenceData; // the unquantised reference behind `reference`
    ImageComparison comparison;
    BuildReport compile;
    QString error; // set when something could not run at all
    // With CheckOptions::floatTarget: pixels whose R, G or B came out NaN or
    // infinite (drawn magenta in `gpu`); -1 when not rendered that way.
    qint64 nonFinitePixels = -1;

    bool matches() const
    {
        return error.isEmpty() && comparison.pixelsCompared > 0 && comparison.psnr >= kMinPsnrDb
            && comparison.maxError <= kMaxErrorSteps;
    }
};

// What checkAgainstReference() may vary besides the scene.
struct CheckOptions {
    // Replacement stages; a stage left empty is the shipped one of scene.shading.
    std::optional<ShaderSource> vertex;
    std::optional<ShaderSource> fragment;
    // Maps a scene's mesh (as written) to the builtin whose analytic surface
    // the reference ray-casts for it (e.g. a Blender cube -> "builtin:cube").
    QHash<QString, QString> standIns;
    // What the reference computes; idealShadingFor(scene.shading) when unset
    // (Phong for Gouraud and flat: the error is what they get wrong).
    std::optional<ReferenceShading> reference;
    // When set, every object is drawn with this mesh instead of its own (a
    // coarser tessellation, say); the reference still ray-casts the analytic
    // surface the object's mesh names, and culling follows the object's mesh.
    std::shared_ptr<const MeshData> meshOverride;
    // Render into a 32-bit float target and quantise on the CPU as an 8-bit
    // target would (round(clamp(I, 0, 1) · 255)), counting non-finite pixels.
    bool floatTarget = false;
};

// Renders `scene` offscreen (kTestImageSide², no MSAA) with the shipped
// shaders of scene.shading, or with replacement stages, and compares it with
// the ray-cast reference. Creates its own context; call from the GUI thread
// of a QGuiApplication.
RenderCheck checkAgainstReference(const Scene &scene, const CheckOptions &options);
RenderCheck checkAgainstReference(const Scene &scene,
                                  const std::optional<ShaderSource> &vertex = std::nullopt,
                                  const std::optional<ShaderSource> &fragment = std::nullopt,
                                  const QHash<QString, QString> &standIns = {});

// Saves gpu / reference / heatmap PNGs under $PHONGLAB_TEST_ARTIFACTS (or
// the system temp dir) so a failing render can be looked at; returns the folder.
// The heatmap uses check.referenceData (ray-cast again, as Phong, if empty).
QString saveArtifacts(const QString &name, const RenderCheck &check, const Scene &scene,
                      const QHash<QString, QString> &standIns = {});

// Reads tests/data/<relative> as a shader source.
ShaderSource testShader(const QString &relative);
ShaderSource shippedShader(const QString &fileName);

// A scene from tests/data/scenes/<name>.json (aborts the test on failure).
Scene loadTestScene(const QString &name);

} // namespace phonglab::test
