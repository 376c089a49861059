#include "MeshInfoCommand.h"
#include "core/support/Language.h"

#include "cli/common/CliCommon.h"
#include "mesh/loading/MeshLoader.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <variant>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct MeshInfoCommandWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::MeshInfoCommand)
};

namespace {

struct MeshInfoArgs {
    QString path;
    bool json = false;
    NormalOptions normals;
};

const char kUsage[] = "usage: phonglab mesh-info FILE [--json] [--normals METHOD] [--crease DEG]";

std::variant<MeshInfoArgs, int> parseArgs(const QStringList &arguments)
{
    QCommandLineParser parser;
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  MeshInfoCommandWords::tr("Show help."));
    const QCommandLineOption json(QStringLiteral("json"), MeshInfoCommandWords::tr("Print JSON."));
    const QCommandLineOption normals(QStringLiteral("normals"),
                                     MeshInfoCommandWords::tr("Normal method."),
                                     QStringLiteral("method"));
    const QCommandLineOption crease(
        QStringLiteral("crease"), MeshInfoCommandWords::tr("Crease angle."), QStringLiteral("deg"));

    const QString synopsis = QString::fromLatin1(kUsage);
    const QString helpText =
        synopsis
        + MeshInfoCommandWords::tr(
            "\n\nLoads a mesh (OBJ, PLY, OFF, STL, OM) the way a scene does and prints its "
            "vertices,\n"
            "faces, where the normals came from, bounds, split vertices, warnings and load "
            "time.\n\n"
            "  --json            machine-readable output; keys: vertices, faces, normals (\"file\" "
            "or\n"
            "                    \"computed\"), normal_method, bounds, warnings, load_ms, and "
            "more\n"
            "  --normals METHOD  auto (default: the file's, else angle), flat, average, area, "
            "angle\n"
            "  --crease DEG      split computed normals where faces meet at more than DEG "
            "degrees; a file's\n"
            "                    own normals are used as written (--normals angle computes "
            "them instead)\n\n"
            "Exit status: 0 loaded (maybe with warnings), 1 cannot be loaded, 2 wrong arguments.");
    const auto usage = [&](const QString &message) { return usageError(message, synopsis); };
    if (const std::optional<int> exit =
            parseOrExit(parser, arguments, {help, {json, normals, crease}, {}}, synopsis, helpText))
        return *exit;
    if (parser.positionalArguments().size() != 1)
        return usage(MeshInfoCommandWords::tr("expected exactly one mesh file"));

    MeshInfoArgs args;
    args.path = parser.positionalArguments().first();
    args.json = parser.isSet(json);
    if (parser.isSet(normals)) {
        const auto method = normalMethodFromName(parser.value(normals));
        if (!method)
            return usage(
                MeshInfoCommandWords::tr("--normals: unknown method '%1' (known: %2)")
                    .arg(parser.value(normals), normalMethodNames().join(QStringLiteral(", "))));
        args.normals.method = *method;
    }
    if (parser.isSet(crease)) {
        bool ok = false;
        const double degrees = parser.value(crease).toDouble(&ok);
        if (!ok || !(degrees >= 0.0 && degrees <= 180.0))
            return usage(
                MeshInfoCommandWords::tr("--crease: expected degrees in [0, 180], got '%1'")
                    .arg(parser.value(crease)));
        args.normals.creaseAngleDeg = degrees;
    }
    return args;
}

// Floats printed as the shortest decimal that reads back as the same float
// (1.4f, not 1.399999976158142).
double floatToJson(float f)
{
    for (int digits = 6; digits < 9; ++digits) {
        const QString text = QString::number(double(f), 'g', digits);
        if (text.toFloat() == f)
            return text.toDouble();
    }
    return double(f);
}

QJsonArray vec3Json(const glm::vec3 &v)
{
    return QJsonArray{floatToJson(v.x), floatToJson(v.y), floatToJson(v.z)};
}

QString methodDescription(const MeshStats &s)
{
    QString text = normalMethodName(s.normalMethod);
    if (s.creaseAngleDeg)
        text += MeshInfoCommandWords::tr(", crease %1°").arg(*s.creaseAngleDeg);
    return text;
}

void printJson(const QString &path, const MeshLoadResult &r)
{
    const MeshStats &s = r.stats;
    QJsonObject o;
    o.insert(QStringLiteral("file"), path);
    o.insert(QStringLiteral("vertices"), s.fileVertices);
    o.insert(QStringLiteral("faces"), s.fileFaces);
    o.insert(QStringLiteral("normals"),
             s.normalsFromFile ? QStringLiteral("file") : QStringLiteral("computed"));
    o.insert(QStringLiteral("normal_method"),
             s.normalsFromFile                                ? QStringLiteral("file")
                 : path.startsWith(QLatin1String("builtin:")) ? QStringLiteral("analytic")
                                                              : normalMethodName(s.normalMethod));
    // A crease splits computed normals only; the file's are used as written.
    o.insert(QStringLiteral("crease_deg"),
             s.creaseAngleDeg && !s.normalsFromFile ? QJsonValue(*s.creaseAngleDeg) : QJsonValue());
    o.insert(QStringLiteral("bounds"),
             QJsonObject{{QStringLiteral("min"), vec3Json(s.boundsMin)},
                         {QStringLiteral("max"), vec3Json(s.boundsMax)}});
    o.insert(QStringLiteral("gpu_vertices"), s.vertices);
    o.insert(QStringLiteral("triangles"), s.triangles);
    o.insert(QStringLiteral("split_vertices"), s.splitVertices);
    o.insert(QStringLiteral("closed"), s.closed);
    o.insert(QStringLiteral("warnings"), QJsonArray::fromStringList(r.warnings));
    o.insert(QStringLiteral("load_ms"), s.loadMs);
    o.insert(QStringLiteral("from_cache"), s.fromCache);
    printLine(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Indented)).trimmed());
}

void printText(const QString &path, const MeshLoadResult &r)
{
    const MeshStats &s = r.stats;
    const auto v = [](const glm::vec3 &p) {
        return QStringLiteral("(%1, %2, %3)")
            .arg(sentenceNumber(p.x), sentenceNumber(p.y), sentenceNumber(p.z));
    };
    printLine(MeshInfoCommandWords::tr("file:            %1").arg(path));
    printLine(MeshInfoCommandWords::tr("vertices:        %1").arg(s.fileVertices));
    printLine(MeshInfoCommandWords::tr("faces:           %1").arg(s.fileFaces));
    printLine(MeshInfoCommandWords::tr("triangles:       %1").arg(s.triangles));
    const QString normals = s.normalsFromFile
        ? MeshInfoCommandWords::tr("from the file, per face corner")
        : path.startsWith(QLatin1String("builtin:"))
        ? MeshInfoCommandWords::tr("analytic")
        : MeshInfoCommandWords::tr("computed (%1)").arg(methodDescription(s));
    printLine(MeshInfoCommandWords::tr("normals:         %1").arg(normals));
    printLine(MeshInfoCommandWords::tr("gpu vertices:    %1 (%2 split for differing normals)")
                  .arg(s.vertices)
                  .arg(s.splitVertices));
    printLine(
        MeshInfoCommandWords::tr("bounds:          %1 .. %2").arg(v(s.boundsMin), v(s.boundsMax)));
    printLine(
        MeshInfoCommandWords::tr("surface:         %1")
            .arg(s.closed ? MeshInfoCommandWords::tr("closed") : MeshInfoCommandWords::tr("open")));
    printLine(
        MeshInfoCommandWords::tr("load time:       %1 ms%2")
            .arg(sentenceNumber(s.loadMs, 'f', 1))
            .arg(s.fromCache ? MeshInfoCommandWords::tr(" (from the mesh cache)") : QString()));
    printLine(MeshInfoCommandWords::tr("warnings:        %1").arg(r.warnings.size()));
    for (const QString &w : r.warnings)
        printLine(QStringLiteral("  - ") + w);
}

} // namespace

int runMeshInfo(int argc, char **argv)
{
    const auto parsed = parseArgs(argumentsFrom(argc, argv).mid(1));
    if (const int *code = std::get_if<int>(&parsed))
        return *code;
    const MeshInfoArgs &args = std::get<MeshInfoArgs>(parsed);
    const MeshLoadResult result = loadMesh(args.path, args.normals);
    if (!result.ok()) {
        printError(result.error);
        return kExitFailure;
    }
    if (args.normals.creaseAngleDeg && result.stats.normalsFromFile)
        printErrLine(QStringLiteral("phonglab: warning: %1: %2")
                         .arg(args.path,
                              MeshInfoCommandWords::tr(
                                  "--crease %1 is not used: the file has normals of its own, "
                                  "used as written (--normals angle computes them with the "
                                  "crease)")
                                  .arg(sentenceNumber(*args.normals.creaseAngleDeg))));
    if (args.json)
        printJson(args.path, result);
    else
        printText(args.path, result);
    return kExitOk;
}

} // namespace phonglab::cli
