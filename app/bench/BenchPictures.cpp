#include "BenchPictures.h"

#include "core/reference/ImageMetrics.h"
#include "render/gl/QtImages.h"

#include <QCoreApplication>
#include <QPainter>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct BenchPicturesWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::BenchPictures)
};

QImage benchTriptych(const QImage &rendered, const ReferenceImage &reference,
                     const glm::dvec3 &background, int bandPx,
                     const std::vector<std::uint8_t> *compared, const QString &caption)
{
    const int w = rendered.width(), h = rendered.height();
    constexpr int kGap = 4;
    constexpr int kCaption = 26;
    QImage out(3 * w + 2 * kGap, h + 2 * kCaption, QImage::Format_RGB32);
    out.fill(QColor(24, 24, 28));
    QPainter painter(&out);
    painter.drawImage(0, kCaption, rendered);
    painter.drawImage(w + kGap, kCaption, toQImage(reference.toImage(background)));
    painter.drawImage(2 * (w + kGap), kCaption,
                      toQImage(errorHeatmap(toRgbImage(rendered), reference, bandPx, compared)));
    painter.setPen(QColor(235, 235, 235));
    QFont font = painter.font();
    font.setPixelSize(14);
    painter.setFont(font);
    painter.drawText(QRect(6, 0, out.width() - 12, kCaption), Qt::AlignVCenter | Qt::AlignLeft,
                     caption);
    const QStringList labels{
        QStringLiteral("GPU"), BenchPicturesWords::tr("CPU reference (exact)"),
        BenchPicturesWords::tr(
            "error: green exact, yellow 4/255, red ≥ 8/255, blue silhouette band")};
    for (int i = 0; i < 3; ++i)
        painter.drawText(QRect(i * (w + kGap) + 6, kCaption + h, w - 12, kCaption),
                         Qt::AlignVCenter | Qt::AlignLeft, labels[i]);
    return out;
}

} // namespace phonglab
