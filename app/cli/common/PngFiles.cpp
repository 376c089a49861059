#include "PngFiles.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QImageWriter>
#include <QSaveFile>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct PngFilesWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::PngFiles)
};

QString pngNameProblem(const QString &option, const QString &path)
{
    const QByteArray suffix = QFileInfo(path).suffix().toLower().toUtf8();
    if (suffix.isEmpty() || suffix == "png")
        return {};
    static const QList<QByteArray> others = [] {
        QList<QByteArray> formats = QImageWriter::supportedImageFormats();
        formats << "jpg"
                << "jpeg"
                << "gif"
                << "webp"
                << "tif"
                << "tiff"
                << "bmp"
                << "svg"
                << "exr"
                << "tga"
                << "heic"
                << "avif"
                << "jxl";
        return formats;
    }();
    if (!others.contains(suffix))
        return {};
    return PngFilesWords::tr("%1 %2: PhongLab writes PNG images only; give a name that ends "
                             "in .png")
        .arg(option, path);
}

Result<> writePng(const QImage &image, const QString &path)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fail(PngFilesWords::tr("cannot write: %1").arg(file.errorString()));
    if (!image.save(&file, "PNG")) {
        file.cancelWriting();
        return fail(PngFilesWords::tr("PNG encoding failed"));
    }
    if (!file.commit())
        return fail(PngFilesWords::tr("cannot write: %1").arg(file.errorString()));
    return {};
}

} // namespace phonglab::cli
