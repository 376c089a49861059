// What naming several mistakes at once costs (prints figures; not a test).
//
//   build/tests/bench/bench_mistake_sets [--runs N]
//
// On the check scene (assets/scenes/check.json), at 320x240 and 800x600: the
// shipped Phong shaders with one mistake (reflect-incident) and with three
// (halfway-vector, attenuation and ambient), drawn on the GPU once each, then
// checked again and again (checkRender: the diagnosis, and for the three the
// search for the smallest set that explains them). A `phonglab check` is the
// reference (ray casting, made once per scene and size) plus the checking;
// both ratios are printed, each against its peer in the same run.
#include "BenchHelpers.h"
#include "CheckScene.h"
#include "ShaderMutations.h"
#include "core/check/MistakeSets.h"
#include "headless/HeadlessPlatform.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/QtImages.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QGuiApplication>
#include <cstdio>

using namespace phonglab;
using namespace phonglab::test;

namespace {

// The median wall time of `runs` verdicts, in ms, and the last report.
double checkOnceMs(const RgbImage &image, const CheckReference &reference, int runs,
                   CheckReport *report)
{
    std::vector<double> ms;
    for (int i = 0; i < runs; ++i) {
        QElapsedTimer clock;
        clock.start();
        *report = checkRender(image, reference);
        ms.push_back(double(clock.nsecsElapsed()) / 1e6);
    }
    return bench::percentile(ms, 0.5);
}

} // namespace

int main(int argc, char **argv)
{
    chooseCommandPlatform(); // no display server needed
    QGuiApplication app(argc, argv);
    QCommandLineParser parser;
    const QCommandLineOption runs(QStringLiteral("runs"), QStringLiteral("verdicts per shader"),
                                  QStringLiteral("n"), QStringLiteral("5"));
    parser.addOption(runs);
    parser.addHelpOption();
    parser.process(app);
    const int n = std::max(1, parser.value(runs).toInt());

    const Scene scene = loadCheckScene();
    OffscreenRenderer offscreen;
    if (!offscreen.create())
        qFatal("no OpenGL context");
    if (!offscreen.renderer().setScene(scene))
        qFatal("check scene not drawn");
    const ShaderPair one = withMistake(ShaderMistake::ReflectIncident);
    const ShaderPair three = withMistakes({{ShaderMistake::Attenuation, 0},
                                           {ShaderMistake::Ambient, 0},
                                           {ShaderMistake::HalfwayVector, 0}});
    std::printf("%-9s %12s %14s %14s %14s %14s\n", "size", "reference ms", "check 1 ms",
                "check 3 ms", "check 3/1", "check 3/1");
    for (const QSize size : {QSize(320, 240), QSize(800, 600)}) {
        QElapsedTimer clock;
        clock.start();
        const CheckReference reference = makeTestCheckReference(scene, size.width(), size.height());
        const double referenceMs = double(clock.nsecsElapsed()) / 1e6;
        CheckReport oneReport, threeReport;
        const double oneMs = checkOnceMs(drawPair(offscreen, one, size), reference, n, &oneReport);
        const double threeMs =
            checkOnceMs(drawPair(offscreen, three, size), reference, n, &threeReport);
        std::printf("%-9s %12.0f %14.1f %14.1f %14.2f %14.2f\n",
                    qPrintable(QStringLiteral("%1x%2").arg(size.width()).arg(size.height())),
                    referenceMs, oneMs, threeMs, threeMs / oneMs,
                    (referenceMs + threeMs) / (referenceMs + oneMs));
        std::printf("          one: %s\n          three: %s (explains %.0f %%)\n",
                    qPrintable(mistakeSetName(oneReport.diagnosis.together)),
                    qPrintable(mistakeSetName(threeReport.diagnosis.together)),
                    100.0 * threeReport.diagnosis.together.explains);
    }
    std::printf("check 3/1: a whole check (the reference, made once per scene and size, plus "
                "the checking) of the three-mistake shader against the one-mistake shader's\n");
    return 0;
}
