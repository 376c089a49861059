// The pictures of docs/checking-your-shader.md (not a test):
//
//   xvfb-run -a build/tests/tools/make_check_figures docs/images/check
//
// For each classic mistake, made in the shipped Phong shaders as a student
// makes it (tests/support/ShaderMutations), on the check scene: one strip of
// the exact image, the render with the mistake, and the check's heatmap,
// labelled, plus the verdict line the check prints.
#include "CheckScene.h"
#include "ShaderMutations.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/QtImages.h"

#include <QDir>
#include <QGuiApplication>
#include <QPainter>
#include <cstdio>

using namespace phonglab;
using namespace phonglab::test;

namespace {

QImage strip(const QImage &exact, const QImage &yours, const QImage &heatmap, const QString &title)
{
    constexpr int kHeader = 22;
    QImage out(exact.width() * 3 + 8, exact.height() + kHeader, QImage::Format_RGB32);
    out.fill(QColor(32, 32, 36));
    QPainter p(&out);
    p.setPen(Qt::white);
    const QImage *images[] = {&exact, &yours, &heatmap};
    const QString labels[] = {QStringLiteral("exact"), title,
                              QStringLiteral("heatmap |yours - exact|")};
    for (int i = 0; i < 3; ++i) {
        const int x = i * (exact.width() + 4);
        p.drawText(QRect(x + 4, 2, exact.width() - 8, kHeader - 4),
                   Qt::AlignLeft | Qt::AlignVCenter, labels[i]);
        p.drawImage(x, kHeader, *images[i]);
    }
    return out;
}

} // namespace

int main(int argc, char **argv)
{
    QGuiApplication app(argc, argv);
    const QString folder =
        argc > 1 ? QString::fromLocal8Bit(argv[1]) : QStringLiteral("docs/images/check");
    QDir().mkpath(folder);
    const Scene scene = loadCheckScene();
    const CheckReference reference = makeTestCheckReference(scene);
    OffscreenRenderer offscreen;
    Result<> ready = offscreen.create();
    if (ready)
        ready = offscreen.renderer().setScene(scene);
    if (!ready) {
        std::fprintf(stderr, "%s\n", qPrintable(ready.error()));
        return 1;
    }
    const QImage exact = toQImage(reference.exact.toImage(reference.background));
    const auto render = [&](const ShaderPair &shaders) {
        const BuildReport program =
            offscreen.renderer().setProgramSources(shaders.vertex, shaders.fragment);
        if (!program.ok)
            qFatal("%s", qPrintable(program.errorSummary()));
        return offscreen.renderImage(QSize(kCheckWidth, kCheckHeight));
    };
    QStringList names{QStringLiteral("shipped")};
    names << shaderMistakeKeys();
    for (const QString &name : names) {
        const ShaderPair shaders = name == QLatin1String("shipped")
            ? shippedPhong()
            : withMistake(*shaderMistakeFromKey(name));
        const QImage yours = render(shaders);
        const CheckReport report = checkRender(toRgbImage(yours), reference);
        const QString path = QDir(folder).filePath(name + QStringLiteral(".png"));
        if (!strip(exact, yours, toQImage(checkHeatmap(toRgbImage(yours), reference)), name)
                 .save(path)) {
            std::fprintf(stderr, "cannot write %s\n", qPrintable(path));
            return 1;
        }
        std::printf("%s: %s\n", qPrintable(name), qPrintable(checkSummary(report)));
    }
    return 0;
}
