#pragma once
#include "core/check/PixelTerms.h"
#include "core/view/Camera.h"

#include <QImage>
#include <QWidget>
#include <optional>

namespace phonglab {

// Drawn over the viewport: the check's pictures and the inspector's arrows.
// Transparent to the mouse, so the view below still orbits; the split
// divider is dragged by its own handle (a sibling above this).
enum class OverlayMode {
    Off,     // the live render alone
    Heatmap, // |yours − exact| per pixel, with a legend
    Split,   // the exact image left of the divider, yours right of it
    Exact,   // the exact image alone
};

class CheckOverlay : public QWidget
{
    Q_OBJECT

public:
    explicit CheckOverlay(QWidget *viewport);

    void setMode(OverlayMode mode);
    OverlayMode mode() const { return m_mode; }
    // The pictures of the newest check; `fresh` false while the view has
    // moved on and a newer check is on its way (drawn dimmed meanwhile).
    void setImages(const QImage &exact, const QImage &heatmap);
    void setFresh(bool fresh);
    // Where the divider sits, 0..1 of the width.
    void setDivider(double fraction);
    double divider() const { return m_divider; }

    // Arrows N, V and each light's L and R at an inspected point, in world
    // coordinates so they stay put as the camera moves; drawn with `camera`.
    void setArrows(const std::optional<PixelTerms> &terms, const glm::dmat4 &viewAtInspection);
    void setCamera(const Camera &camera);
    bool hasArrows() const { return m_terms.has_value(); }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    void paintLegend(QPainter &painter) const;
    void paintArrows(QPainter &painter) const;

    OverlayMode m_mode = OverlayMode::Off;
    QImage m_exact;
    QImage m_heatmap;
    bool m_fresh = true;
    double m_divider = 0.5;
    std::optional<PixelTerms> m_terms;
    glm::dmat3 m_cameraToWorld{1.0};
    Camera m_camera;
};

} // namespace phonglab
