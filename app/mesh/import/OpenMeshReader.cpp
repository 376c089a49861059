#include "OpenMeshReader.h"

#include "MeshTextTokens.h"
#include "OpenMeshHeaders.h"
#include "PolygonSoupImporter.h"

#include <QCoreApplication>

#include <QFile>
#include <QTemporaryDir>

#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct OpenMeshReaderWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::OpenMeshReader)
};

namespace {

// Routes OpenMesh's console streams into buffers while it exists, then puts
// the previous ones back. OpenMesh sends these to std::cerr / std::clog /
// std::cout by default; a GUI has no use for that and the user needs the
// messages as warnings instead. The streams' buffers are swapped (rdbuf)
// rather than their targets changed with mostream::connect/disconnect:
// OpenMesh's disconnect() forgets the target object connect() allocated
// without deleting it, a leak on every file read.
class ConsoleCapture
{
public:
    ConsoleCapture()
    {
        for (int i = 0; i < 3; ++i)
            m_previous[i] = stream(i).rdbuf(&m_buffers[i]);
    }

    ~ConsoleCapture()
    {
        for (int i = 0; i < 3; ++i)
            stream(i).rdbuf(m_previous[i]);
    }

    // The distinct lines written to omerr so far.
    QStringList errorLines()
    {
        stream(0).flush();
        QStringList lines;
        std::istringstream in(m_buffers[0].str());
        for (std::string line; std::getline(in, line);) {
            const QString l = QString::fromStdString(line).trimmed();
            if (!l.isEmpty() && !lines.contains(l))
                lines << l;
        }
        return lines;
    }

    ConsoleCapture(const ConsoleCapture &) = delete;
    ConsoleCapture &operator=(const ConsoleCapture &) = delete;

private:
    static std::ostream &stream(int i) { return i == 0 ? omerr() : i == 1 ? omlog() : omout(); }

    std::stringbuf m_buffers[3];
    std::streambuf *m_previous[3] = {};
};

std::mutex &openMeshMutex()
{
    static std::mutex mutex;
    return mutex;
}

// The OM reader stops at the end marker OpenMesh writes after the last
// chunk. Running into the end of the file instead means it was cut short,
// and the reader would have carried on with whatever a failed read leaves in
// its variables.
bool readOm(std::istream &in, PolygonSoupImporter &importer, OpenMesh::IO::Options options,
            QString &error)
{
    const bool ok = OpenMesh::IO::IOManager().read(in, "om", importer, options);
    if (in.eof())
        error = OpenMeshReaderWords::tr("the file ends before its end marker (truncated?)");
    return ok && !in.eof();
}

// Hands `read` the precheck's cleaned copy when there is one (STL without
// non-finite triangles, OM without custom properties), else the file.
template <typename Read>
bool readFileOrCopy(const QString &path, const MeshFilePrecheck &check, QString &error, Read read)
{
    if (!check.rewritten.empty()) {
        std::istringstream in(check.rewritten, std::ios::binary);
        return read(in);
    }
    std::ifstream in(QFile::encodeName(path).toStdString(), std::ios::binary);
    if (!in) {
        error = OpenMeshReaderWords::tr("cannot open the file");
        return false;
    }
    return read(in);
}

bool readInto(PolygonSoupImporter &importer, const QString &path, const MeshFilePrecheck &check,
              OpenMesh::IO::Options options, QString &error)
{
    OpenMesh::IO::_IOManager_ &io = OpenMesh::IO::IOManager();
    if (check.format == MeshFileFormat::Stl) {
        // Told binary or ascii explicitly, as the precheck decided it.
        if (check.binary)
            options += OpenMesh::IO::Options::Binary;
        return readFileOrCopy(path, check, error, [&](std::istream &in) {
            return io.read(in, "stl", importer, options);
        });
    }
    if (check.format == MeshFileFormat::Om)
        return readFileOrCopy(path, check, error, [&](std::istream &in) {
            return readOm(in, importer, options, error);
        });
    if (!check.rewritten.empty()) {
        // A cleaned OFF text. The OFF reader's stream entry point keeps the
        // header flags of the previous file, so it goes through a file too.
        QTemporaryDir dir;
        QFile cleaned(dir.filePath(QStringLiteral("cleaned.off")));
        if (!dir.isValid() || !cleaned.open(QIODevice::WriteOnly)
            || cleaned.write(check.rewritten.data(), qint64(check.rewritten.size()))
                != qint64(check.rewritten.size())) {
            error = OpenMeshReaderWords::tr(
                "cannot write a cleaned copy of the OFF file to the temporary folder");
            return false;
        }
        cleaned.close();
        return io.read(QFile::encodeName(cleaned.fileName()).toStdString(), importer, options);
    }
    return io.read(QFile::encodeName(path).toStdString(), importer, options);
}

struct ReaderRun {
    bool ok = false;
    QStringList messages; // the distinct lines OpenMesh wrote to omerr
};

// Runs the reader with its console captured. Any exception becomes `error`:
// a hostile file costs a message, never the app.
ReaderRun runReader(PolygonSoupImporter &importer, const QString &path,
                    const MeshFilePrecheck &check, OpenMesh::IO::Options options, QString &error)
{
    ReaderRun run;
    ConsoleCapture capture;
    try {
        run.ok = readInto(importer, path, check, options, error);
    } catch (const PolygonSoupImporter::Cancelled &) {
        error = QStringLiteral("cancelled");
    } catch (const std::bad_alloc &) {
        error = OpenMeshReaderWords::tr("out of memory while reading the file");
    } catch (const std::exception &e) {
        error =
            OpenMeshReaderWords::tr("the reader failed: %1").arg(QString::fromLocal8Bit(e.what()));
    } catch (...) {
        error = OpenMeshReaderWords::tr("the reader failed");
    }
    run.messages = capture.errorLines();
    return run;
}

// The reader's complaints after a successful read, the first few of them.
void addReaderMessages(const QStringList &messages, QStringList &warnings)
{
    constexpr int kMaxMessages = 5;
    for (int i = 0; i < messages.size() && i < kMaxMessages; ++i)
        warnings << QStringLiteral("OpenMesh: %1").arg(messages[i]);
    if (messages.size() > kMaxMessages)
        warnings << QStringLiteral("OpenMesh: %1 more")
                        .arg(
                            meshtext::counted(messages.size() - kMaxMessages,
                                              QT_TRANSLATE_NOOP("phonglab::MeshText", "message"),
                                              QT_TRANSLATE_NOOP("phonglab::MeshText", "messages")));
}

// What was read against what the header (or the precheck) declared.
void addCountWarnings(const MeshFilePrecheck &check, std::size_t vertices, std::size_t faceCalls,
                      QStringList &warnings)
{
    if (check.declaredVertices && vertices != check.declaredVertices
        && check.format != MeshFileFormat::Stl)
        warnings << OpenMeshReaderWords::tr("read %1 of the %2 the header declares")
                        .arg(vertices)
                        .arg(
                            meshtext::counted(check.declaredVertices,
                                              QT_TRANSLATE_NOOP("phonglab::MeshText", "vertex"),
                                              QT_TRANSLATE_NOOP("phonglab::MeshText", "vertices")));
    if (check.format == MeshFileFormat::Stl && faceCalls < check.declaredFaces) {
        // OpenMesh's STL reader merges corners by position and skips
        // triangles left with a repeated corner.
        warnings << OpenMeshReaderWords::tr("dropped %1 with two corners at the same position")
                        .arg(meshtext::counted(
                            check.declaredFaces - faceCalls,
                            QT_TRANSLATE_NOOP("phonglab::MeshText", "triangle"),
                            QT_TRANSLATE_NOOP("phonglab::MeshText", "triangles")));
    } else if (check.declaredFaces && faceCalls != check.declaredFaces) {
        warnings << OpenMeshReaderWords::tr("read %1 of the %2 the header declares")
                        .arg(faceCalls)
                        .arg(meshtext::counted(check.declaredFaces,
                                               QT_TRANSLATE_NOOP("phonglab::MeshText", "face"),
                                               QT_TRANSLATE_NOOP("phonglab::MeshText", "faces")));
    }
}

} // namespace

MeshReadResult readWithOpenMesh(const QString &path, const MeshFilePrecheck &check,
                                const std::function<bool(double)> &progress)
{
    std::lock_guard<std::mutex> lock(openMeshMutex());
    MeshReadResult result;
    PolygonSoupImporter importer;
    const quint64 expected = check.declaredVertices + check.declaredFaces;
    if (progress && expected) {
        importer.setProgress(
            [&](std::size_t n) { return progress(std::min(1.0, double(n) / double(expected))); },
            64 * 1024);
    }
    // Every element takes at least a byte of the file.
    importer.setReserveLimit(std::size_t(check.fileSize));

    // Face normals only from STL: that is where they are the file's normals;
    // an OM file's are derived data.
    OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexNormal;
    if (check.format == MeshFileFormat::Stl)
        options += OpenMesh::IO::Options::FaceNormal;

    const ReaderRun run = runReader(importer, path, check, options, result.error);
    if (!result.error.isEmpty())
        return result;
    if (!run.ok) {
        result.error = run.messages.isEmpty()
            ? OpenMeshReaderWords::tr("OpenMesh could not read the file")
            : OpenMeshReaderWords::tr("OpenMesh could not read the file: %1")
                  .arg(run.messages.first());
        return result;
    }
    addReaderMessages(run.messages, result.warnings);

    const std::size_t faceCalls = importer.faceCallCount();
    PolygonMesh mesh = importer.takeMesh(result.warnings);
    addCountWarnings(check, mesh.positions.size(), faceCalls, result.warnings);
    if (mesh.faceCount() == 0) {
        result.error = OpenMeshReaderWords::tr("no faces were read");
        return result;
    }
    result.mesh = std::move(mesh);
    return result;
}

} // namespace phonglab
