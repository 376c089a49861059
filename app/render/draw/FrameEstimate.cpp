#include "FrameEstimate.h"

#include "Renderer.h"
#include "render/gl/LentContext.h"

#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <algorithm>

namespace phonglab {

namespace {

double timedRender(Renderer &renderer, const QSize &size)
{
    QElapsedTimer clock;
    clock.start();
    renderer.render(size);
    QOpenGLContext::currentContext()->functions()->glFinish();
    return double(clock.nsecsElapsed()) / 1e6;
}

double area(const QSize &size)
{
    return double(size.width()) * size.height();
}

} // namespace

double estimateFrameMs(Renderer &renderer, const QSize &pixelSize, double limitMs)
{
    const auto timed = [&](const QSize &size) { return timedRender(renderer, size); };
    const QSize small = (pixelSize / 4).expandedTo(QSize(8, 8));
    const QSize medium = (pixelSize / 2).expandedTo(QSize(16, 16));
    const double fullPixels = double(pixelSize.width()) * pixelSize.height();
    const double smallPixels = double(small.width()) * small.height();
    const double mediumPixels = double(medium.width()) * medium.height();
    // A whole frame costs at least as much as a part of it, and at most the
    // part's time scaled by the area (the per-draw part does not grow): one
    // part settles most programs either way.
    const double a = timed(small);
    if (a > limitMs)
        return a;
    if (a * fullPixels / smallPixels <= limitMs)
        return a * fullPixels / smallPixels;
    const double b = timed(medium);
    if (b > limitMs)
        return b;
    const double perPixel = std::max(0.0, (b - a) / (mediumPixels - smallPixels));
    const double perDraw = std::max(0.0, a - perPixel * smallPixels);
    return perDraw + perPixel * fullPixels;
}

double trialFrameMs(Renderer &renderer, const LentContext &lent, const QSize &pixelSize,
                    double limitMs)
{
    if (lent.frame && lent.frame->pixels == pixelSize) {
        const QSize probe = (pixelSize / 16).expandedTo(QSize(8, 8));
        const double probeMs = timedRender(renderer, probe);
        if (probeMs > limitMs)
            return probeMs;
        if (probeMs * area(pixelSize) / area(probe) <= std::max(limitMs, kBlindFrameMs)
            && drawLoanFrame(lent))
            return lent.frame->drawMs;
    }
    const double estimate = estimateFrameMs(renderer, pixelSize, limitMs);
    if (estimate <= limitMs)
        drawLoanFrame(lent); // the frame the view would draw next, shown from the loan
    return estimate;
}

} // namespace phonglab
