#include "MeshFileReader.h"

#include "MeshFilePrecheck.h"
#include "ObjReader.h"
#include "OpenMeshReader.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <exception>
#include <new>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct MeshFileReaderWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::MeshFileReader)
};

namespace {

MeshReadResult readChecked(const QString &path, MeshFileFormat format,
                           const std::function<bool(double)> &progress)
{
    MeshReadResult result;
    if (progress && !progress(0.0)) {
        result.error = QStringLiteral("cancelled");
        return result;
    }
    MeshFilePrecheck check = precheckMeshFile(path, format);
    if (!check.ok()) {
        result.error = check.error;
        return result;
    }
    result = format == MeshFileFormat::Obj ? readObjFile(path, progress)
                                           : readWithOpenMesh(path, check, progress);
    result.warnings = check.warnings + result.warnings;
    if (result.ok() && result.mesh->faceCount() == 0) {
        result.mesh.reset();
        result.error = MeshFileReaderWords::tr("the file has no faces");
    }
    if (result.ok() && progress)
        progress(1.0);
    return result;
}

} // namespace

MeshReadResult readMeshFile(const QString &path, const std::function<bool(double)> &progress)
{
    const std::optional<MeshFileFormat> format = meshFileFormatForPath(path);
    if (!format) {
        MeshReadResult result;
        const QString suffix = QFileInfo(path).suffix();
        result.error = MeshFileReaderWords::tr("unsupported file type '%1' (supported: %2)")
                           .arg(suffix.isEmpty() ? MeshFileReaderWords::tr("no suffix")
                                                 : QLatin1Char('.') + suffix,
                                supportedMeshFileSuffixes());
        return result;
    }
    // Nothing a broken file does may escape as an exception: the readers
    // catch their own, this catches what the checks or copies might throw.
    try {
        return readChecked(path, *format, progress);
    } catch (const std::bad_alloc &) {
        MeshReadResult result;
        result.error = MeshFileReaderWords::tr("out of memory while reading the file");
        return result;
    } catch (const std::exception &e) {
        MeshReadResult result;
        result.error =
            MeshFileReaderWords::tr("reading failed: %1").arg(QString::fromLocal8Bit(e.what()));
        return result;
    }
}

} // namespace phonglab
