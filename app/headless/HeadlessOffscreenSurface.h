#pragma once
#include <QOffscreenSurface>
#include <qpa/qplatformoffscreensurface.h>

namespace phonglab::headless {

// A QOffscreenSurface with no EGL surface behind it: the headless context is
// made current surfaceless, so the surface only has to exist for Qt.
class HeadlessOffscreenSurface : public QPlatformOffscreenSurface
{
public:
    explicit HeadlessOffscreenSurface(QOffscreenSurface *surface)
        : QPlatformOffscreenSurface(surface)
        , m_format(surface->requestedFormat())
    {
    }
    QSurfaceFormat format() const override { return m_format; }
    bool isValid() const override { return true; }

private:
    QSurfaceFormat m_format;
};

} // namespace phonglab::headless
