#include "CheckOverlay.h"

#include <QFontMetrics>

#include <QLinearGradient>
#include <QPainter>
#include <QPainterPath>

namespace phonglab {

namespace {

constexpr double kArrowLengthFraction = 0.12; // of the point's distance from the eye

struct Arrow {
    glm::dvec3 direction; // world, unit
    QColor color;
    QString label;
};

} // namespace

CheckOverlay::CheckOverlay(QWidget *viewport)
    : QWidget(viewport)
{
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    setObjectName(QStringLiteral("checkOverlay"));
    hide();
}

void CheckOverlay::setMode(OverlayMode mode)
{
    m_mode = mode;
    setVisible(m_mode != OverlayMode::Off || m_terms);
    update();
}

void CheckOverlay::setImages(const QImage &exact, const QImage &heatmap)
{
    m_exact = exact;
    m_heatmap = heatmap;
    m_fresh = true;
    update();
}

void CheckOverlay::setFresh(bool fresh)
{
    m_fresh = fresh;
    update();
}

void CheckOverlay::setDivider(double fraction)
{
    m_divider = std::clamp(fraction, 0.0, 1.0);
    update();
}

void CheckOverlay::setArrows(const std::optional<PixelTerms> &terms,
                             const glm::dmat4 &viewAtInspection)
{
    m_terms = terms;
    m_cameraToWorld = glm::transpose(glm::dmat3(viewAtInspection)); // a rotation: its inverse
    setVisible(m_mode != OverlayMode::Off || m_terms);
    update();
}

void CheckOverlay::setCamera(const Camera &camera)
{
    m_camera = camera;
    if (m_terms)
        update();
}

void CheckOverlay::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.setOpacity(m_fresh ? 1.0 : 0.45);
    const QRect all = rect();
    switch (m_mode) {
    case OverlayMode::Off: break;
    case OverlayMode::Heatmap:
        if (!m_heatmap.isNull()) {
            painter.drawImage(all, m_heatmap);
            painter.setOpacity(1.0);
            paintLegend(painter);
        }
        break;
    case OverlayMode::Split:
        if (!m_exact.isNull()) {
            const int x = int(std::lround(m_divider * width()));
            const QRectF source(0, 0, m_divider * m_exact.width(), m_exact.height());
            painter.drawImage(QRectF(0, 0, x, height()), m_exact, source);
            painter.setOpacity(1.0);
            painter.setPen(QPen(Qt::white, 2));
            painter.drawLine(x, 0, x, height());
            painter.drawText(QRect(x - 70, 6, 64, 20), Qt::AlignRight, tr("exact"));
            painter.drawText(QRect(x + 6, 6, 64, 20), Qt::AlignLeft, tr("yours"));
        }
        break;
    case OverlayMode::Exact:
        if (!m_exact.isNull())
            painter.drawImage(all, m_exact);
        break;
    }
    painter.setOpacity(1.0);
    if (m_terms)
        paintArrows(painter);
}

// The heatmap's colours (errorHeatmap() in core/reference/ImageMetrics): a ramp from
// exact to 8/255 or more, and what the two flat colours mean.
void CheckOverlay::paintLegend(QPainter &painter) const
{
    // As wide as its words in the run's language and font ("silhouette band,
    // not checked" was cut at "not chec" in a fixed box).
    const QFontMetrics metrics(painter.font());
    const QString band = tr("silhouette band, not checked");
    const int line = metrics.height();
    const int width = std::max(180, metrics.horizontalAdvance(band) + 40);
    const QRect box(this->width() - width - 10, height() - (2 * line + 40), width, 2 * line + 30);
    painter.fillRect(box, QColor(0, 0, 0, 170));
    QLinearGradient ramp(box.left() + 10, 0, box.right() - 10, 0);
    ramp.setColorAt(0.0, QColor(0, 64, 0));
    ramp.setColorAt(0.124, QColor(0, 64, 0));
    ramp.setColorAt(0.125, QColor(64, 255, 0));
    ramp.setColorAt(0.5, QColor(255, 255, 0));
    ramp.setColorAt(1.0, QColor(255, 0, 0));
    const QRect rampRect(box.left() + 10, box.top() + 8, box.width() - 20, 12);
    painter.fillRect(rampRect, ramp);
    painter.setPen(Qt::white);
    const QRect numbers(rampRect.left(), rampRect.bottom() + 3, rampRect.width(), line);
    painter.drawText(numbers, Qt::AlignLeft, tr("exact"));
    painter.drawText(numbers, Qt::AlignHCenter, tr("4/255"));
    painter.drawText(numbers, Qt::AlignRight, tr("≥ 8/255"));
    const int bandTop = numbers.bottom() + 6;
    painter.fillRect(QRect(box.left() + 10, bandTop + (line - 10) / 2, 10, 10), QColor(0, 0, 96));
    painter.drawText(QRect(box.left() + 24, bandTop, box.width() - 30, line), Qt::AlignLeft, band);
}

void CheckOverlay::paintArrows(QPainter &painter) const
{
    const PixelTerms &t = *m_terms;
    const double aspect = double(width()) / double(std::max(1, height()));
    const glm::dmat4 toClip = m_camera.projectionMatrix(aspect) * m_camera.viewMatrix();
    const auto project = [&](const glm::dvec3 &world) -> std::optional<QPointF> {
        const glm::dvec4 c = toClip * glm::dvec4(world, 1.0);
        if (c.w <= 1e-9)
            return std::nullopt;
        return QPointF((c.x / c.w * 0.5 + 0.5) * width(), (0.5 - c.y / c.w * 0.5) * height());
    };
    std::vector<Arrow> arrows{{m_cameraToWorld * t.N, QColor(80, 160, 255), QStringLiteral("N")},
                              {m_cameraToWorld * t.V, QColor(240, 240, 240), QStringLiteral("V")}};
    for (const LightTerms &l : t.lights) {
        arrows.push_back(
            {m_cameraToWorld * l.L, QColor(255, 210, 60), QStringLiteral("L%1").arg(l.light + 1)});
        if (t.shading == ReferenceShading::BlinnPhong)
            arrows.push_back({m_cameraToWorld * l.H, QColor(255, 110, 200),
                              QStringLiteral("H%1").arg(l.light + 1)});
        else
            arrows.push_back({m_cameraToWorld * l.R, QColor(255, 110, 200),
                              QStringLiteral("R%1").arg(l.light + 1)});
    }
    const double length = kArrowLengthFraction * glm::length(t.positionCamera);
    const std::optional<QPointF> origin = project(t.positionWorld);
    if (!origin)
        return;
    painter.setRenderHint(QPainter::Antialiasing);
    for (const Arrow &a : arrows) {
        const std::optional<QPointF> tip =
            project(t.positionWorld + length * glm::normalize(a.direction));
        if (!tip)
            continue;
        painter.setPen(QPen(a.color, 2));
        painter.drawLine(*origin, *tip);
        const QPointF d = *tip - *origin;
        const double n = std::hypot(d.x(), d.y());
        if (n > 1.0) {
            const QPointF u = d / n, side(-u.y(), u.x());
            QPainterPath head;
            head.moveTo(*tip);
            head.lineTo(*tip - 8 * u + 4 * side);
            head.lineTo(*tip - 8 * u - 4 * side);
            head.closeSubpath();
            painter.fillPath(head, a.color);
        }
        painter.drawText(*tip + QPointF(4, -4), a.label);
    }
    painter.setPen(QPen(Qt::black, 1));
    painter.setBrush(Qt::white);
    painter.drawEllipse(*origin, 3, 3);
}

} // namespace phonglab
