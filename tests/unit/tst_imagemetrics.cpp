// Image comparison: PSNR/RMSE worked out by hand, the silhouette band, and
// inputs that do not fit together.

#include "core/reference/ImageMetrics.h"
#include "render/gl/QtImages.h"

#include <QtTest>
#include <cmath>

using namespace phonglab;

namespace {

struct Rgb {
    int r = 0, g = 0, b = 0;
    bool operator==(const Rgb &) const = default;
};

RgbImage filled(int w, int h, Rgb color)
{
    RgbImage image(w, h);
    image.fill(uchar(color.r), uchar(color.g), uchar(color.b));
    return image;
}

Rgb pixelAt(const RgbImage &image, int x, int y)
{
    const std::uint8_t *p = image.pixel(x, y);
    return {p[0], p[1], p[2]};
}

// A 20×20 reference covering the square [5, 15)² with I = 0.5 everywhere
// (encoded 127.5 -> 128).
ReferenceImage squareReference()
{
    ReferenceImage ref(20, 20);
    for (int y = 5; y < 15; ++y) {
        for (int x = 5; x < 15; ++x) {
            ref.coverage[ref.index(x, y)] = 1;
            ref.color[ref.index(x, y)] = glm::dvec3(0.5);
        }
    }
    return ref;
}

// What a perfect render of squareReference() looks like on a black background.
RgbImage squareRender()
{
    RgbImage image = filled(20, 20, Rgb{0, 0, 0});
    for (int y = 5; y < 15; ++y)
        for (int x = 5; x < 15; ++x)
            image.setPixel(x, y, 128, 128, 128);
    return image;
}

} // namespace

class TestImageMetrics : public QObject
{
    Q_OBJECT

private slots:
    void identicalImages()
    {
        const RgbImage a = filled(16, 8, Rgb{10, 200, 30});
        const ImageComparison c = compareImages(a, a);
        QVERIFY(std::isinf(c.psnr) && c.psnr > 0);
        QCOMPARE(c.rmse, 0.0);
        QCOMPARE(c.maxError, 0);
        QCOMPARE(c.pixelsCompared, qint64(128));
        QVERIFY2(c.summary().startsWith(QStringLiteral("PSNR inf dB")), qPrintable(c.summary()));
    }

    void knownOffset()
    {
        // Red +3 on all 100 pixels: 300 channel values, 100 of them off by 3.
        // MSE = 100·9 / 300 = 3, RMSE = √3 = 1.7320508,
        // PSNR = 20·log10(255/√3) = 20·(2.4065402 - 0.2385606) = 43.359591 dB.
        const RgbImage a = filled(10, 10, Rgb{100, 50, 25});
        const RgbImage b = filled(10, 10, Rgb{103, 50, 25});
        const ImageComparison c = compareImages(a, b);
        QCOMPARE(c.pixelsCompared, qint64(100));
        QCOMPARE(c.maxError, 3);
        QCOMPARE(c.worstPixel, QPoint(0, 0)); // the first of the equally bad
        QVERIFY(std::abs(c.rmse - 1.7320508) < 1e-6);
        QVERIFY(std::abs(c.psnr - 43.359591) < 1e-5);
        QCOMPARE(c.summary(),
                 QStringLiteral("PSNR 43.36 dB, RMSE 1.73, max 3/255 at (0,0), 100 px"));
    }

    void singleWorstPixel()
    {
        // Green -5 at (7, 2) of 10×4: 120 values, one off by 5.
        // RMSE = √(25/120) = 0.4564355; PSNR = 20·log10(255/0.4564355) = 54.94 dB.
        const RgbImage a = filled(10, 4, Rgb{9, 9, 9});
        RgbImage b = a;
        b.setPixel(7, 2, 9, 4, 9);
        const ImageComparison c = compareImages(a, b);
        QCOMPARE(c.maxError, 5);
        QCOMPARE(c.worstPixel, QPoint(7, 2));
        QVERIFY(std::abs(c.rmse - 0.4564355) < 1e-6);
        QVERIFY(std::abs(c.psnr - 54.9430) < 1e-3);
    }

    void qtImagesConvert()
    {
        // Any QImage converts: ARGB32 and RGB888 (rows padded to 4 bytes at
        // width 5) with the same colours are the same RgbImage, and back.
        QImage a(5, 3, QImage::Format_RGB888);
        a.fill(qRgb(1, 2, 3));
        a.setPixel(4, 2, qRgb(7, 8, 9));
        const RgbImage b = toRgbImage(a.convertToFormat(QImage::Format_ARGB32));
        QVERIFY(std::isinf(compareImages(toRgbImage(a), b).psnr));
        QCOMPARE(pixelAt(b, 4, 2), (Rgb{7, 8, 9}));
        QCOMPARE(toQImage(b), a);
        QVERIFY(toRgbImage(QImage()).isNull());
    }

    void referencePerfectRender()
    {
        const ImageComparison c = compareWithReference(squareRender(), squareReference(), 0);
        QVERIFY(std::isinf(c.psnr));
        QCOMPARE(c.maxError, 0);
    }

    void bandExcludesSilhouette_data()
    {
        // The 10×10 square's outermost ring has uncovered neighbours, so it is
        // silhouette (as is the ring just outside, uncovered anyway). Pixels more
        // than b away from both rings: a (8 - 2b)² square.
        QTest::addColumn<int>("band");
        QTest::addColumn<qint64>("compared");
        QTest::newRow("0") << 0 << qint64(64);
        QTest::newRow("1") << 1 << qint64(36);
        QTest::newRow("2") << 2 << qint64(16);
        QTest::newRow("4") << 4 << qint64(0);
    }

    void bandExcludesSilhouette()
    {
        QFETCH(int, band);
        QFETCH(qint64, compared);
        // Ruin the square's edge ring in the render: the band must hide it.
        RgbImage rendered = squareRender();
        for (int i = 5; i < 15; ++i) {
            for (const QPoint &p : {QPoint(i, 5), QPoint(i, 14), QPoint(5, i), QPoint(14, i)})
                rendered.setPixel(p.x(), p.y(), 255, 0, 255);
        }
        const ImageComparison c = compareWithReference(rendered, squareReference(), band);
        QCOMPARE(c.pixelsCompared, compared);
        if (compared > 0) {
            QVERIFY(std::isinf(c.psnr));
        } else {
            QCOMPARE(c.psnr, 0.0); // nothing compared is not a pass
        }
    }

    void interiorErrorIsFound()
    {
        // One interior pixel off by 2 in blue, compared over the 6×6 interior
        // (band 1): 108 values, one off by 2 -> RMSE = √(4/108) = 0.19245009.
        RgbImage rendered = squareRender();
        rendered.setPixel(9, 10, 128, 128, 130);
        const ImageComparison c = compareWithReference(rendered, squareReference(), 1);
        QCOMPARE(c.pixelsCompared, qint64(36));
        QCOMPARE(c.maxError, 2);
        QCOMPARE(c.worstPixel, QPoint(9, 10));
        QVERIFY(std::abs(c.rmse - 0.19245009) < 1e-7);
    }

    void referenceIsQuantisedAndClamped()
    {
        // I = 1.7 encodes to 255 and -0.2 to 0: a render of 255 / 0 is exact.
        ReferenceImage ref(3, 3);
        ref.coverage.assign(9, 1);
        ref.color.assign(9, glm::dvec3(1.7, -0.2, 0.5));
        const ImageComparison c = compareWithReference(filled(3, 3, Rgb{255, 0, 128}), ref, 0);
        QCOMPARE(c.pixelsCompared, qint64(9)); // fully covered: no silhouette at all
        QCOMPARE(c.maxError, 0);
    }

    void sizeMismatch()
    {
        const ImageComparison a = compareImages(filled(4, 4, Rgb{}), filled(4, 5, Rgb{}));
        QCOMPARE(a.pixelsCompared, qint64(0));
        QCOMPARE(a.psnr, 0.0);
        QCOMPARE(a.summary(), QStringLiteral("no pixels compared"));
        const ImageComparison b = compareWithReference(filled(19, 20, Rgb{}), squareReference(), 1);
        QCOMPARE(b.pixelsCompared, qint64(0));
        QCOMPARE(b.psnr, 0.0);
        QCOMPARE(compareWithReference(RgbImage(), ReferenceImage(), 0).pixelsCompared, qint64(0));
        QCOMPARE(compareImages(RgbImage(), RgbImage()).psnr, 0.0);
        QVERIFY(errorHeatmap(filled(19, 20, Rgb{}), squareReference(), 1).isNull());
    }

    // The bench's comparison also counts pixels the render covers where the
    // reference shows background (a coarse mesh bulging out of the outline).
    void outsideBandCountsBothCoverages()
    {
        const ReferenceImage ref = squareReference();
        const glm::dvec3 black(0.0);
        RgbImage render = squareRender();
        BandComparison exact = compareOutsideBand(render, ref, black, 1);
        QCOMPARE(exact.error.maxError, 0);
        QCOMPARE(exact.coverageErrors, qint64(0));
        // Interior of the square minus the 1 px band on both sides of its edge: 6×6.
        QCOMPARE(exact.error.pixelsCompared, qint64(36));

        // A blob of surface far outside the outline: 2 px, 128 steps off each.
        render.setPixel(1, 1, 128, 128, 128);
        render.setPixel(18, 18, 128, 128, 128);
        const BandComparison bulge = compareOutsideBand(render, ref, black, 1);
        QCOMPARE(bulge.coverageErrors, qint64(2));
        QCOMPARE(bulge.error.maxError, 128);
        QCOMPARE(bulge.error.pixelsCompared, qint64(38));
        // compareWithReference() only looks where the reference has a surface.
        QCOMPARE(compareWithReference(render, ref, 1).maxError, 0);

        // A hole in the surface is a coverage error too.
        RgbImage hole = squareRender();
        hole.setPixel(10, 10, 0, 0, 0);
        const BandComparison holed = compareOutsideBand(hole, ref, black, 1);
        QCOMPARE(holed.coverageErrors, qint64(1));
        QCOMPARE(holed.error.maxError, 128);
    }

    void outsideBandMask()
    {
        const ReferenceImage ref = squareReference();
        RgbImage render = squareRender();
        render.setPixel(8, 8, 140, 128, 128);   // 12 off, inside the mask
        render.setPixel(11, 11, 160, 128, 128); // 32 off, outside it
        std::vector<std::uint8_t> mask(ref.color.size(), 0);
        for (int y = 7; y < 10; ++y)
            for (int x = 7; x < 10; ++x)
                mask[ref.index(x, y)] = 1;
        const BandComparison masked = compareOutsideBand(render, ref, glm::dvec3(0.0), 1, &mask);
        QCOMPARE(masked.error.pixelsCompared, qint64(9));
        QCOMPARE(masked.error.maxError, 12);
        QCOMPARE(compareOutsideBand(render, ref, glm::dvec3(0.0), 1).error.maxError, 32);
        // A mask of the wrong size compares nothing rather than reading past it.
        std::vector<std::uint8_t> wrong(3, 1);
        QCOMPARE(compareOutsideBand(render, ref, glm::dvec3(0.0), 1, &wrong).error.pixelsCompared,
                 qint64(0));
    }

    // A plane seen at any angle has 1/z affine in the image: no contour
    // however fast its depth changes. A step between two surfaces is one.
    void occludingContours()
    {
        ReferenceImage ref(40, 20);
        for (int y = 0; y < 20; ++y) {
            for (int x = 0; x < 40; ++x) {
                ref.coverage[ref.index(x, y)] = 1;
                ref.depth[ref.index(x, y)] = 1.0 / (0.9 - 0.02 * x + 0.005 * y); // steep plane
            }
        }
        for (std::uint8_t c : occludingContourPixels(ref))
            QCOMPARE(c, std::uint8_t(0));
        // Columns 20.. move 1 % further away: another surface behind the first.
        for (int y = 0; y < 20; ++y)
            for (int x = 20; x < 40; ++x)
                ref.depth[ref.index(x, y)] *= 1.01;
        const std::vector<std::uint8_t> contour = occludingContourPixels(ref);
        for (int y = 0; y < 20; ++y) {
            for (int x = 0; x < 40; ++x) {
                const bool atStep = x == 19 || x == 20;
                QVERIFY2(bool(contour[ref.index(x, y)]) == atStep,
                         qPrintable(QStringLiteral("(%1,%2)").arg(x).arg(y)));
            }
        }
        const std::vector<std::uint8_t> wide = dilatePixels(contour, 40, 20, 2);
        QCOMPARE(wide[ref.index(17, 5)], std::uint8_t(1));
        QCOMPARE(wide[ref.index(16, 5)], std::uint8_t(0));
        QVERIFY(dilatePixels(contour, 41, 20, 2).empty()); // wrong size: nothing, no overrun
    }

    void heatmap()
    {
        RgbImage rendered = squareRender();
        rendered.setPixel(9, 10, 128, 128, 140); // 12 off: full red
        const RgbImage map = errorHeatmap(rendered, squareReference(), 1);
        QCOMPARE(map.width, 20);
        QCOMPARE(map.height, 20);
        QCOMPARE(pixelAt(map, 9, 10), (Rgb{255, 0, 0}));
        QCOMPARE(pixelAt(map, 8, 8), (Rgb{0, 64, 0})); // compared, exact
        QCOMPARE(pixelAt(map, 6, 6), (Rgb{0, 0, 96})); // in the band
        QCOMPARE(pixelAt(map, 0, 0), (Rgb{0, 0, 0}));  // uncovered
    }
};

QTEST_APPLESS_MAIN(TestImageMetrics)
#include "tst_imagemetrics.moc"
