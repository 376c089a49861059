#pragma once
#include <QProxyStyle>

namespace phonglab {

// The application's style with large menu icons, for a menu whose icons are
// pictures (File → Examples' thumbnails) rather than glyphs: menus draw their
// icons at the small icon size (16 pixels), where a scene is a smudge.
class ThumbnailMenuStyle : public QProxyStyle
{
    Q_OBJECT

public:
    static constexpr int kIconSide = 48; // pixels; a 4:3 thumbnail shows at 48×36

    explicit ThumbnailMenuStyle(QObject *parent = nullptr);

    int pixelMetric(PixelMetric metric, const QStyleOption *option = nullptr,
                    const QWidget *widget = nullptr) const override;
};

} // namespace phonglab
