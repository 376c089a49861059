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

// Every option of `bench`, declared once.
struct BenchOptionSet {
    QCommandLineOption help{{QStringLiteral("h"), QStringLiteral("help")},
                            BenchArgsWords::tr("Show help.")};
    QCommandLineOption scene{QStringLiteral("scene"), BenchArgsWords::tr("Scene file."),
                             QStringLiteral("file")};
    QCommandLineOption quick{QStringLiteral("quick"), BenchArgsWords::tr("Short run.")};
    QCommandLineOption out{QStringLiteral("out"), BenchArgsWords::tr("Output folder."),
                           QStringLiteral("dir")};
    QCommandLineOption budget{QStringLiteral("budget"), BenchArgsWords::tr("Error budget."),
                              QStringLiteral("spec")};
    QCommandLineOption size{QStringLiteral("size"), BenchArgsWords::tr("Frame size."),
                            QStringLiteral("WxH")};
    QCommandLineOption frames{QStringLiteral("frames"), BenchArgsWords::tr("Timed frames."),
                              QStringLiteral("n")};
    QCommandLineOption lights{QStringLiteral("lights"), BenchArgsWords::tr("Light counts."),
                              QStringLiteral("list")};
    QCommandLineOption methods{QStringLiteral("methods"), QStringLiteral("Methods."),
                               QStringLiteral("list")};
    QCommandLineOption details{QStringLiteral("details"), BenchArgsWords::tr("Detail fractions."),
                               QStringLiteral("list")};
    QCommandLineOption images{QStringLiteral("images"), BenchArgsWords::tr("Write pictures.")};
    QCommandLineOption normals{QStringLiteral("normals"),
                               BenchArgsWords::tr("Normal-method study.")};
    QCommandLineOption from{QStringLiteral("from"), BenchArgsWords::tr("Earlier results."),
                            QStringLiteral("csv")};
    QCommandLineOption path{QStringLiteral("path"), BenchArgsWords::tr("Camera path."),
                            QStringLiteral("spec")};
    QCommandLineOption pathFrames{QStringLiteral("path-frames"), BenchArgsWords::tr("Path frames."),
                                  QStringLiteral("n")};
};

// Each reader below fills its part of `args` from `parser` and returns the
// usage error of a wrong value, or an empty string.

// --from and --path: what the run measures, and what may not go with it.
QString readWhatIsMeasured(const QCommandLineParser &parser, const BenchOptionSet &o,
                           BenchArgs &args)
{
    args.fromCsv = parser.value(o.from);
    if (parser.isSet(o.from)) {
        for (const QCommandLineOption *measuring :
             {&o.scene, &o.quick, &o.size, &o.frames, &o.lights, &o.methods, &o.details, &o.images,
              &o.normals})
            if (parser.isSet(*measuring))
                return BenchArgsWords::tr("--from measures nothing: --%1 does not go with it")
                    .arg(measuring->names().constLast());
        if (args.fromCsv.isEmpty())
            return BenchArgsWords::tr("--from: empty file name");
    }
    args.path = parser.value(o.path);
    if (parser.isSet(o.path)) {
        for (const QCommandLineOption *sweep :
             {&o.quick, &o.lights, &o.methods, &o.details, &o.normals, &o.from})
            if (parser.isSet(*sweep))
                return BenchArgsWords::tr("--path measures a camera path: --%1 does not go with it")
                    .arg(sweep->names().constLast());
        if (args.path.isEmpty())
            return BenchArgsWords::tr("--path: expected orbit, dolly or a keyframe file");
    }
    if (parser.isSet(o.pathFrames)) {
        bool ok = false;
        const int n = parser.value(o.pathFrames).toInt(&ok);
        if (!parser.isSet(o.path))
            return BenchArgsWords::tr("--path-frames goes with --path orbit or --path dolly");
        if (!ok || n < 2 || n > 10000)
            return BenchArgsWords::tr(
                       "--path-frames: expected a whole number from 2 to 10000, got '%1'")
                .arg(parser.value(o.pathFrames));
        args.pathFrames = n;
    }
    return {};
}

// --quick, --scene, --out, --normals, --images.
QString readRunAndOutputs(const QCommandLineParser &parser, const BenchOptionSet &o,
                          BenchArgs &args)
{
    args.sizeGiven = parser.isSet(o.size);
    args.framesGiven = parser.isSet(o.frames);
    args.quick = parser.isSet(o.quick);
    args.options = args.quick ? BenchOptions::quick() : BenchOptions::full();
    args.options.scenes = parser.isSet(o.scene) ? parser.values(o.scene)
                                                : defaultScenes(args.quick || parser.isSet(o.path));
    args.outDir = parser.isSet(o.out) ? parser.value(o.out) : QStringLiteral("phonglab-bench");
    if (args.outDir.isEmpty())
        return BenchArgsWords::tr("--out: empty folder name");
    args.normalStudy = args.fromCsv.isEmpty() && (parser.isSet(o.normals) || !args.quick);
    if (parser.isSet(o.images))
        args.options.imageDir = QDir(args.outDir).filePath(QStringLiteral("images"));
    return {};
}

// --budget, --size, --frames.
QString readBudgetAndFrames(const QCommandLineParser &parser, const BenchOptionSet &o,
                            BenchArgs &args)
{
    if (parser.isSet(o.budget)) {
        const auto parsed = ErrorBudget::parse(parser.value(o.budget));
        if (!parsed)
            return BenchArgsWords::tr("--budget: expected N (max error N/255) or psnr:DB, got '%1'")
                .arg(parser.value(o.budget));
        args.budget = *parsed;
    }
    if (parser.isSet(o.size)) {
        const auto parsed = parseSizeArgument(parser.value(o.size), 16, 8192);
        if (!parsed)
            return BenchArgsWords::tr(
                       "--size: expected WxH with 16..8192 pixels per side, got '%1'")
                .arg(parser.value(o.size));
        args.options.size = *parsed;
    }
    if (parser.isSet(o.frames)) {
        bool ok = false;
        const int n = parser.value(o.frames).toInt(&ok);
        // A path times every one of its frames: fewer per frame are enough.
        const int least = parser.isSet(o.path) ? 3 : 20;
        if (!ok || n < least || n > 10000)
            return BenchArgsWords::tr(
                       "--frames: expected a whole number from %1 to 10000, got '%2'")
                .arg(least)
                .arg(parser.value(o.frames));
        args.options.frames = n;
    }
    return {};
}

// --lights: counts 1..kMaxLights and/or the scene's own.
QString readLights(const QCommandLineParser &parser, const BenchOptionSet &o, BenchArgs &args)
{
    if (!parser.isSet(o.lights))
        return {};
    bool sceneOwn = false;
    const auto counts =
        parseList<int>(parser.value(o.lights), [&](const QString &s) -> std::optional<int> {
            if (s == QLatin1String("scene")) {
                sceneOwn = true;
                return 0; // removed below
            }
            bool ok = false;
            const int n = s.toInt(&ok);
            return ok && n >= 1 && n <= kMaxLights ? std::optional<int>(n) : std::nullopt;
        });
    if (!counts)
        return BenchArgsWords::tr(
                   "--lights: expected counts 1..%1 and/or 'scene', comma separated, got '%2'")
            .arg(kMaxLights)
            .arg(parser.value(o.lights));
    args.options.lightCounts.clear();
    for (int n : *counts)
        if (n > 0)
            args.options.lightCounts.push_back(n);
    args.options.sceneLights = sceneOwn;
    return {};
}

// --methods and --details: what the sweep draws.
QString readMethodsAndDetails(const QCommandLineParser &parser, const BenchOptionSet &o,
                              BenchArgs &args)
{
    if (parser.isSet(o.methods)) {
        const auto parsed = parseList<ShadingMethod>(parser.value(o.methods), [](const QString &s) {
            const auto m = shadingFromName(s);
            return m && *m != ShadingMethod::Normals ? m : std::nullopt;
        });
        if (!parsed)
            return BenchArgsWords::tr(
                       "--methods: expected names from flat, gouraud, faceted, blinn-phong, phong, "
                       "got '%1'")
                .arg(parser.value(o.methods));
        args.options.methods = *parsed;
    }
    if (parser.isSet(o.details)) {
        const auto parsed = parseList<double>(
            parser.value(o.details), [](const QString &s) -> std::optional<double> {
                bool ok = false;
                const double d = s.toDouble(&ok);
                return ok && d > 0.0 && d <= 1.0 ? std::optional<double>(d) : std::nullopt;
            });
        if (!parsed)
            return BenchArgsWords::tr(
                       "--details: expected fractions in (0, 1], comma separated, got '%1'")
                .arg(parser.value(o.details));
        args.options.details = *parsed;
    }
    return {};
}

} // namespace

std::variant<BenchArgs, int> parseBenchArgs(const QStringList &arguments)
{
    QCommandLineParser parser;
    const BenchOptionSet o;
    if (const std::optional<int> exit =
            parseOrExit(parser, arguments,
                        {o.help,
                         {o.scene, o.quick, o.out, o.budget, o.size, o.frames, o.lights, o.methods,
                          o.details, o.images, o.normals, o.from, o.path, o.pathFrames},
                         {QStringLiteral("scene")}},
                        kSynopsis, helpText()))
        return *exit;
    if (!parser.positionalArguments().isEmpty())
        return usageError(BenchArgsWords::tr("unexpected argument '%1' (scenes go after --scene)")
                              .arg(parser.positionalArguments().first()),
                          kSynopsis);
    BenchArgs args;
    for (const auto read : {readWhatIsMeasured, readRunAndOutputs, readBudgetAndFrames, readLights,
                            readMethodsAndDetails})
        if (const QString wrong = read(parser, o, args); !wrong.isEmpty())
            return usageError(wrong, kSynopsis);
    return args;
}

} // namespace phonglab::cli
