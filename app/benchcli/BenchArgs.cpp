#include "BenchArgs.h"

#include "cli/common/CliCommon.h"
#include "core/scene/PointLight.h"
#include "core/scene/ResourcePaths.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>

#include <optional>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct BenchArgsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::BenchArgs)
};

namespace {

const QString kSynopsis = BenchArgsWords::tr(
    "usage: phonglab bench [--scene FILE ...] [--quick] [--out DIR] [--budget SPEC] [--size WxH]\n"
    "                      [--frames N] [--lights LIST] [--methods LIST] [--details LIST] "
    "[--images] [--normals]\n"
    "       phonglab bench --from results.csv [--out DIR] [--budget SPEC]\n"
    "       phonglab bench --path orbit|dolly|FILE.json [--path-frames N] [--scene FILE ...] "
    "[--out DIR]\n"
    "                      [--budget SPEC] [--size WxH] [--frames N] [--images]");

QString helpText()
{
    return kSynopsis
        + BenchArgsWords::tr(
               "\n\n"
               "Measures every shading method at every level of detail under 1, 4 and 8 lights "
               "(and the\n"
               "scene's own lights): frame time against the error from the CPU double-precision "
               "reference.\n\n"
               "  --scene FILE     a scene to measure (repeatable); default: the shipped default "
               "(tree and\n"
               "                   cloud), sphere, torus and grazing scenes (--quick: default and "
               "sphere)\n"
               "  --quick          400x300 px, detail 100/12.5/1.6 %: about 20 s on two cores\n"
               "  --out DIR        where results.csv, fit.csv, chart.png and chart.svg go (default "
               "./phonglab-bench)\n"
               "  --budget SPEC    error budget for the fit: N (max error N/255, default 2) or "
               "psnr:DB\n"
               "  --size WxH       frame size (default 800x600, --quick 400x300)\n"
               "  --frames N       timed frames per configuration after 3 warm-up frames, at least "
               "20 (default 20)\n"
               "  --lights LIST    light counts, comma separated, 1..8, and/or 'scene' (default "
               "1,4,8,scene)\n"
               "  --methods LIST   shading methods, comma separated (default "
               "flat,gouraud,faceted,blinn-phong,phong)\n"
               "  --details LIST   detail fractions in (0, 1], comma separated, e.g. "
               "1,0.25,0.0625\n"
               "  --images         also write render | reference | error pictures into DIR/images\n"
               "  --from CSV       measure nothing: fit and chart the rows of an earlier "
               "results.csv (e.g.\n"
               "                   against another --budget); writes fit.csv and the chart into "
               "DIR\n"
               "  --normals        the normal-method study (DIR/normals.csv, normals.png/svg) in a "
               "--quick run\n"
               "                   too (a full run always has it)\n"
               "  --path SPEC      instead of the sweep: draw each scene along a camera path with "
               "auto detail and\n"
               "                   unseen lights left out, every frame against the reference; "
               "SPEC is orbit (one\n"
               "                   turn moving out to 2.5x), dolly (from just outside the scene "
               "to 32x away) or a\n"
               "                   keyframe file (docs/speed-vs-accuracy.md). Prints 'frames over "
               "budget: K of N';\n"
               "                   writes DIR/path.csv and DIR/path.png/svg. Default scenes: "
               "default and sphere;\n"
               "                   400x300 px, 10 timed frames per path frame\n"
               "  --path-frames N  frames of an orbit or dolly, 2..10000 (default 24)\n\n"
               "Frame time is the median wall time of render + glFinish (on llvmpipe a timer query "
               "misses the\n"
               "rasterizer threads); gpu_ms in results.csv is GL_TIME_ELAPSED on real GPUs. Errors "
               "are in 8-bit\n"
               "steps, more than 2 px from a silhouette (the outline and every occluding contour). "
               "Blinn-Phong\n"
               "uses the matched exponent 4n (n = the material's shininess), as "
               "shaders/blinn-phong.frag does.\n\n"
               "Exit status: 0 success, 1 a scene failed to load or render, 2 wrong arguments.");
}

// Parses each comma-separated item with `item`; nullopt on the first bad one.
template <typename T, typename F>
std::optional<std::vector<T>> parseList(const QString &text, F item)
{
    std::vector<T> out;
    for (const QString &part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const auto value = item(part.trimmed());
        if (!value)
            return std::nullopt;
        out.push_back(*value);
    }
    if (out.empty())
        return std::nullopt;
    return out;
}

QStringList defaultScenes(bool quick)
{
    QStringList names{QStringLiteral("default"), QStringLiteral("sphere")};
    if (!quick)
        names << QStringLiteral("torus") << QStringLiteral("grazing");
    QStringList paths;
    for (const QString &n : names)
        paths << assetPath(QStringLiteral("scenes/%1.json").arg(n));
    return paths;
}

} // namespace

std::variant<BenchArgs, int> parseBenchArgs(const QStringList &arguments)
{
    QCommandLineParser parser;
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  BenchArgsWords::tr("Show help."));
    const QCommandLineOption scene(QStringLiteral("scene"), BenchArgsWords::tr("Scene file."),
                                   QStringLiteral("file"));
    const QCommandLineOption quick(QStringLiteral("quick"), BenchArgsWords::tr("Short run."));
    const QCommandLineOption out(QStringLiteral("out"), BenchArgsWords::tr("Output folder."),
                                 QStringLiteral("dir"));
    const QCommandLineOption budget(QStringLiteral("budget"), BenchArgsWords::tr("Error budget."),
                                    QStringLiteral("spec"));
    const QCommandLineOption size(QStringLiteral("size"), BenchArgsWords::tr("Frame size."),
                                  QStringLiteral("WxH"));
    const QCommandLineOption frames(QStringLiteral("frames"), BenchArgsWords::tr("Timed frames."),
                                    QStringLiteral("n"));
    const QCommandLineOption lights(QStringLiteral("lights"), BenchArgsWords::tr("Light counts."),
                                    QStringLiteral("list"));
    const QCommandLineOption methods(QStringLiteral("methods"), QStringLiteral("Methods."),
                                     QStringLiteral("list"));
    const QCommandLineOption details(
        QStringLiteral("details"), BenchArgsWords::tr("Detail fractions."), QStringLiteral("list"));
    const QCommandLineOption images(QStringLiteral("images"),
                                    BenchArgsWords::tr("Write pictures."));
    const QCommandLineOption normals(QStringLiteral("normals"),
                                     BenchArgsWords::tr("Normal-method study."));
    const QCommandLineOption from(QStringLiteral("from"), BenchArgsWords::tr("Earlier results."),
                                  QStringLiteral("csv"));
    const QCommandLineOption path(QStringLiteral("path"), BenchArgsWords::tr("Camera path."),
                                  QStringLiteral("spec"));
    const QCommandLineOption pathFrames(QStringLiteral("path-frames"),
                                        BenchArgsWords::tr("Path frames."), QStringLiteral("n"));

    const auto usage = [](const QString &message) { return usageError(message, kSynopsis); };
    if (const std::optional<int> exit =
            parseOrExit(parser, arguments,
                        {help,
                         {scene, quick, out, budget, size, frames, lights, methods, details, images,
                          normals, from, path, pathFrames},
                         {QStringLiteral("scene")}},
                        kSynopsis, helpText()))
        return *exit;
    if (!parser.positionalArguments().isEmpty())
        return usage(BenchArgsWords::tr("unexpected argument '%1' (scenes go after --scene)")
                         .arg(parser.positionalArguments().first()));

    BenchArgs args;
    args.fromCsv = parser.value(from);
    if (parser.isSet(from)) {
        for (const QCommandLineOption *measuring :
             {&scene, &quick, &size, &frames, &lights, &methods, &details, &images, &normals})
            if (parser.isSet(*measuring))
                return usage(BenchArgsWords::tr("--from measures nothing: --%1 does not go with it")
                                 .arg(measuring->names().constLast()));
        if (args.fromCsv.isEmpty())
            return usage(BenchArgsWords::tr("--from: empty file name"));
    }
    args.path = parser.value(path);
    if (parser.isSet(path)) {
        for (const QCommandLineOption *sweep :
             {&quick, &lights, &methods, &details, &normals, &from})
            if (parser.isSet(*sweep))
                return usage(
                    BenchArgsWords::tr("--path measures a camera path: --%1 does not go with it")
                        .arg(sweep->names().constLast()));
        if (args.path.isEmpty())
            return usage(BenchArgsWords::tr("--path: expected orbit, dolly or a keyframe file"));
    }
    if (parser.isSet(pathFrames)) {
        bool ok = false;
        const int n = parser.value(pathFrames).toInt(&ok);
        if (!parser.isSet(path))
            return usage(
                BenchArgsWords::tr("--path-frames goes with --path orbit or --path dolly"));
        if (!ok || n < 2 || n > 10000)
            return usage(BenchArgsWords::tr(
                             "--path-frames: expected a whole number from 2 to 10000, got '%1'")
                             .arg(parser.value(pathFrames)));
        args.pathFrames = n;
    }
    args.sizeGiven = parser.isSet(size);
    args.framesGiven = parser.isSet(frames);
    args.quick = parser.isSet(quick);
    args.options = args.quick ? BenchOptions::quick() : BenchOptions::full();
    args.options.scenes = parser.isSet(scene) ? parser.values(scene)
                                              : defaultScenes(args.quick || parser.isSet(path));
    args.outDir = parser.isSet(out) ? parser.value(out) : QStringLiteral("phonglab-bench");
    if (args.outDir.isEmpty())
        return usage(BenchArgsWords::tr("--out: empty folder name"));
    args.normalStudy = args.fromCsv.isEmpty() && (parser.isSet(normals) || !args.quick);
    if (parser.isSet(images))
        args.options.imageDir = QDir(args.outDir).filePath(QStringLiteral("images"));

    if (parser.isSet(budget)) {
        const auto parsed = ErrorBudget::parse(parser.value(budget));
        if (!parsed)
            return usage(
                BenchArgsWords::tr("--budget: expected N (max error N/255) or psnr:DB, got '%1'")
                    .arg(parser.value(budget)));
        args.budget = *parsed;
    }
    if (parser.isSet(size)) {
        const auto parsed = parseSizeArgument(parser.value(size), 16, 8192);
        if (!parsed)
            return usage(
                BenchArgsWords::tr("--size: expected WxH with 16..8192 pixels per side, got '%1'")
                    .arg(parser.value(size)));
        args.options.size = *parsed;
    }
    if (parser.isSet(frames)) {
        bool ok = false;
        const int n = parser.value(frames).toInt(&ok);
        // A path times every one of its frames: fewer per frame are enough.
        const int least = parser.isSet(path) ? 3 : 20;
        if (!ok || n < least || n > 10000)
            return usage(
                BenchArgsWords::tr("--frames: expected a whole number from %1 to 10000, got '%2'")
                    .arg(least)
                    .arg(parser.value(frames)));
        args.options.frames = n;
    }
    if (parser.isSet(lights)) {
        bool sceneOwn = false;
        const auto counts =
            parseList<int>(parser.value(lights), [&](const QString &s) -> std::optional<int> {
                if (s == QLatin1String("scene")) {
                    sceneOwn = true;
                    return 0; // removed below
                }
                bool ok = false;
                const int n = s.toInt(&ok);
                return ok && n >= 1 && n <= kMaxLights ? std::optional<int>(n) : std::nullopt;
            });
        if (!counts)
            return usage(
                BenchArgsWords::tr(
                    "--lights: expected counts 1..%1 and/or 'scene', comma separated, got '%2'")
                    .arg(kMaxLights)
                    .arg(parser.value(lights)));
        args.options.lightCounts.clear();
        for (int n : *counts)
            if (n > 0)
                args.options.lightCounts.push_back(n);
        args.options.sceneLights = sceneOwn;
    }
    if (parser.isSet(methods)) {
        const auto parsed = parseList<ShadingMethod>(parser.value(methods), [](const QString &s) {
            const auto m = shadingFromName(s);
            return m && *m != ShadingMethod::Normals ? m : std::nullopt;
        });
        if (!parsed)
            return usage(
                BenchArgsWords::tr(
                    "--methods: expected names from flat, gouraud, faceted, blinn-phong, phong, "
                    "got '%1'")
                    .arg(parser.value(methods)));
        args.options.methods = *parsed;
    }
    if (parser.isSet(details)) {
        const auto parsed =
            parseList<double>(parser.value(details), [](const QString &s) -> std::optional<double> {
                bool ok = false;
                const double d = s.toDouble(&ok);
                return ok && d > 0.0 && d <= 1.0 ? std::optional<double>(d) : std::nullopt;
            });
        if (!parsed)
            return usage(BenchArgsWords::tr(
                             "--details: expected fractions in (0, 1], comma separated, got '%1'")
                             .arg(parser.value(details)));
        args.options.details = *parsed;
    }
    return args;
}

} // namespace phonglab::cli
