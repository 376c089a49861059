#pragma once
#include "ErrorBudget.h"
#include "core/scene/ShadingMethod.h"

#include <QSize>
#include <QStringList>
#include <optional>
#include <vector>

namespace phonglab {

// What one `phonglab bench` run measures. Every scene is drawn with every
// method at every detail under every light setup; quick() and full() are the
// two presets the command offers.
struct BenchOptions {
    QStringList scenes;   // scene files
    QSize size{800, 600}; // frame size for timing and accuracy alike
    int warmupFrames = 3;
    int frames = 20; // timed frames per configuration (median)
    std::vector<double> details{1.0, 1.0 / 4, 1.0 / 16, 1.0 / 64};
    std::vector<int> lightCounts{1, 4, 8};
    bool sceneLights = true; // also the scene's own lights (what fit-to-budget uses)
    std::vector<ShadingMethod> methods{ShadingMethod::Flat, ShadingMethod::Gouraud,
                                       ShadingMethod::Faceted, ShadingMethod::BlinnPhong,
                                       ShadingMethod::Phong};
    int bandPx = 2; // silhouette band left out of the error
    // A pixel belongs to the specular highlight where the reference's
    // specular term reaches this much in some channel (4/255: visible).
    double specularThreshold = 4.0 / 255.0;
    QString imageDir; // when set: render | reference | error pictures per method
    // When set: scenes of two objects or more also get one row per object
    // (BenchRow::object) and the per-object fit under this budget, drawn
    // whole to check it (BenchEngine::objectFits()).
    std::optional<ErrorBudget> objectFitBudget;

    static BenchOptions quick();
    static BenchOptions full();
};

} // namespace phonglab
