#include "ImportMeshCommand.h"

#include "cli/common/CliCommon.h"
#include "mesh/loading/MeshImportProcess.h"

#include <QCoreApplication>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ImportMeshCommandWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::ImportMeshCommand)
};

int runImportMesh(int argc, char **argv)
{
    const QStringList args = argumentsFrom(argc, argv);
    NormalOptions normals;
    QString out, path;
    MeshImportLimits limits;
    bool ok = true;
    for (qsizetype i = 2; i < args.size() && ok; ++i) {
        const QString &a = args[i];
        const auto value = [&]() -> QString {
            ok = ok && i + 1 < args.size();
            return ok ? args[++i] : QString();
        };
        if (a == QLatin1String("--")) {
            ok = i + 2 == args.size();
            path = ok ? args[i + 1] : QString();
            break;
        } else if (a == QLatin1String("--normals")) {
            const auto method = normalMethodFromName(value());
            ok = ok && method.has_value();
            normals.method = method.value_or(NormalMethod::Auto);
        } else if (a == QLatin1String("--crease")) {
            normals.creaseAngleDeg = value().toDouble(&ok);
        } else if (a == QLatin1String("--out")) {
            out = value();
        } else if (a == QLatin1String("--address-space-mb")) {
            limits.addressSpaceBytes = value().toLongLong(&ok) * 1024 * 1024;
        } else if (a == QLatin1String("--cpu-seconds")) {
            limits.cpuSeconds = value().toInt(&ok);
        } else {
            ok = false;
        }
    }
    if (!ok || path.isEmpty() || out.isEmpty()) {
        printError(ImportMeshCommandWords::tr(
            "__import-mesh is internal: the app runs it to import a mesh file"));
        return kExitUsage;
    }
    return runMeshImportChild(path, normals, out, limits);
}

} // namespace phonglab::cli
