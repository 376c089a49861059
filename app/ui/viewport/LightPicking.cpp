#include "LightPicking.h"

#include <cmath>
#include <limits>

namespace phonglab {

namespace {

glm::dmat4 viewProjection(const Camera &camera, const QSizeF &view)
{
    const double aspect = view.width() / std::max(1.0, view.height());
    return camera.projectionMatrix(aspect) * camera.viewMatrix();
}

// NDC of `p`, or nothing when it is behind the eye.
bool toNdc(const glm::dmat4 &vp, const glm::dvec3 &p, glm::dvec3 *ndc)
{
    const glm::dvec4 clip = vp * glm::dvec4(p, 1.0);
    if (clip.w <= 0.0)
        return false;
    *ndc = glm::dvec3(clip) / clip.w;
    return true;
}

QPointF toScreen(const glm::dvec3 &ndc, const QSizeF &view)
{
    return {(ndc.x + 1.0) * 0.5 * view.width(), (1.0 - ndc.y) * 0.5 * view.height()};
}

} // namespace

int pickLight(const std::vector<PointLight> &lights, const Camera &camera, const QSizeF &view,
              const QPointF &point, double radiusPx)
{
    const glm::dmat4 vp = viewProjection(camera, view);
    int best = -1;
    double bestDistance = radiusPx;
    for (int i = 0; i < int(lights.size()); ++i) {
        glm::dvec3 ndc;
        if (!toNdc(vp, lights[i].position, &ndc))
            continue;
        const QPointF d = toScreen(ndc, view) - point;
        const double distance = std::hypot(d.x(), d.y());
        if (distance <= bestDistance) {
            bestDistance = distance;
            best = i;
        }
    }
    return best;
}

glm::dvec3 moveInViewPlane(const glm::dvec3 &position, const Camera &camera, const QSizeF &view,
                           const QPointF &point)
{
    const glm::dmat4 vp = viewProjection(camera, view);
    glm::dvec3 ndc;
    if (!toNdc(vp, position, &ndc))
        return position;
    const glm::dvec4 target{2.0 * point.x() / view.width() - 1.0,
                            1.0 - 2.0 * point.y() / view.height(), ndc.z, 1.0};
    const glm::dvec4 world = glm::inverse(vp) * target;
    const glm::dvec3 moved = glm::dvec3(world) / world.w;
    const bool finite = std::isfinite(moved.x) && std::isfinite(moved.y) && std::isfinite(moved.z);
    return finite ? moved : position;
}

glm::dvec3 moveAlongView(const glm::dvec3 &position, const Camera &camera, const QSizeF &view,
                         double deltaYPx)
{
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const double distance = glm::length(position - camera.eye);
    // Dragging the full view height moves the light by its distance to the eye.
    const double step = -deltaYPx / std::max(1.0, view.height()) * distance;
    return position + forward * step;
}

} // namespace phonglab
