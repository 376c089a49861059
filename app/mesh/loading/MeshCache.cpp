#include "MeshCache.h"

#include <QCryptographicHash>
#include <QDataStream>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QStandardPaths>

#include <cstdio>
#include <limits>

namespace phonglab {

namespace {

constexpr quint32 kMagic = 0x50484d43; // "PHMC"
constexpr quint32 kVersion = 2;        // 2: vertex order of split meshes is first use

template <typename T> void writeArray(QDataStream &out, const std::vector<T> &v)
{
    out << quint64(v.size());
    out.writeRawData(reinterpret_cast<const char *>(v.data()), int(v.size() * sizeof(T)));
}

template <typename T> bool readArray(QDataStream &in, std::vector<T> &v, qint64 bytesLeft)
{
    quint64 count = 0;
    in >> count;
    // A count that cannot fit in what is left of the file is corruption:
    // refuse it before allocating.
    if (in.status() != QDataStream::Ok || count > quint64(bytesLeft) / sizeof(T))
        return false;
    v.resize(count);
    const qint64 bytes = qint64(count * sizeof(T));
    return in.readRawData(reinterpret_cast<char *>(v.data()), int(bytes)) == bytes;
}

QDataStream &operator<<(QDataStream &out, const glm::vec3 &v)
{
    return out << v.x << v.y << v.z;
}
QDataStream &operator>>(QDataStream &in, glm::vec3 &v)
{
    return in >> v.x >> v.y >> v.z;
}

void writeStats(QDataStream &out, const MeshStats &s)
{
    out << s.fileVertices << s.fileFaces << s.vertices << s.triangles << s.splitVertices
        << s.normalsFromFile << qint32(s.normalMethod) << s.boundsMin << s.boundsMax << s.closed;
}

bool readStats(QDataStream &in, MeshStats &s)
{
    qint32 method = 0;
    in >> s.fileVertices >> s.fileFaces >> s.vertices >> s.triangles >> s.splitVertices
        >> s.normalsFromFile >> method >> s.boundsMin >> s.boundsMax >> s.closed;
    s.normalMethod = NormalMethod(method);
    return method >= qint32(NormalMethod::Auto) && method <= qint32(NormalMethod::AngleWeighted);
}

// QDataStream reserves a list's declared length before reading it, so a
// corrupt count would ask for gigabytes; every string takes at least the
// four bytes of its length.
bool readStrings(QDataStream &in, QStringList &list, qint64 bytesLeft)
{
    quint32 count = 0;
    in >> count;
    if (in.status() != QDataStream::Ok || count > quint64(bytesLeft) / 4)
        return false;
    list.reserve(count);
    for (quint32 i = 0; i < count && in.status() == QDataStream::Ok; ++i) {
        QString s;
        in >> s;
        list << s;
    }
    return in.status() == QDataStream::Ok;
}

} // namespace

bool MeshCache::enabled()
{
    return qEnvironmentVariableIntValue("PHONGLAB_NO_MESH_CACHE") == 0;
}

QString MeshCache::directory()
{
    const QString fromEnv = qEnvironmentVariable("PHONGLAB_CACHE_DIR");
    if (!fromEnv.isEmpty())
        return fromEnv;
    return QStandardPaths::writableLocation(QStandardPaths::GenericCacheLocation)
        + QStringLiteral("/phonglab/meshes");
}

QString MeshCache::entryPath(const QString &file, const NormalOptions &normals)
{
    const QByteArray hash =
        QCryptographicHash::hash(sourceKey(file, normals), QCryptographicHash::Sha1).toHex();
    return QDir(directory()).filePath(QString::fromLatin1(hash) + QStringLiteral(".phmc"));
}

QByteArray MeshCache::sourceKey(const QString &file, const NormalOptions &normals)
{
    const QFileInfo info(file);
    QByteArray key = info.absoluteFilePath().toUtf8();
    key += '|' + QByteArray::number(info.size());
    key += '|' + QByteArray::number(info.lastModified().toMSecsSinceEpoch());
    key += '|' + normalMethodName(normals.method).toUtf8();
    if (normals.creaseAngleDeg)
        key += '|' + QByteArray::number(*normals.creaseAngleDeg, 'g', 17);
    key += "|v" + QByteArray::number(kVersion);
    return key;
}

std::optional<MeshLoadResult> MeshCache::decode(QIODevice &device,
                                                const std::optional<QByteArray> &expectedKey)
{
    QDataStream in(&device);
    in.setVersion(QDataStream::Qt_6_4);
    quint32 magic = 0, version = 0;
    in >> magic >> version;
    if (in.status() != QDataStream::Ok || magic != kMagic || version != kVersion)
        return std::nullopt;
    QByteArray key;
    in >> key;
    if (in.status() != QDataStream::Ok || (expectedKey && key != *expectedKey))
        return std::nullopt;
    MeshLoadResult result;
    MeshData mesh;
    const bool ok = readStats(in, result.stats)
        && readStrings(in, result.warnings, device.bytesAvailable())
        && readArray(in, mesh.positions, device.bytesAvailable())
        && readArray(in, mesh.normals, device.bytesAvailable())
        && readArray(in, mesh.indices, device.bytesAvailable());
    if (!ok || in.status() != QDataStream::Ok || !mesh.isValid())
        return std::nullopt;
    result.mesh = std::move(mesh);
    return result;
}

bool MeshCache::encode(QIODevice &device, const QByteArray &key, const MeshLoadResult &result)
{
    if (!result.mesh)
        return false;
    const std::size_t largest = result.mesh->positions.size() * sizeof(glm::vec3);
    if (largest > std::size_t(std::numeric_limits<int>::max()) / 2)
        return false; // QDataStream's raw blocks are int-sized
    QDataStream out(&device);
    out.setVersion(QDataStream::Qt_6_4);
    out << kMagic << kVersion << key;
    writeStats(out, result.stats);
    out << result.warnings;
    writeArray(out, result.mesh->positions);
    writeArray(out, result.mesh->normals);
    writeArray(out, result.mesh->indices);
    return out.status() == QDataStream::Ok;
}

std::optional<MeshLoadResult> MeshCache::read(const QString &file, const NormalOptions &normals)
{
    if (!enabled())
        return std::nullopt;
    QFile entry(entryPath(file, normals));
    if (!entry.open(QIODevice::ReadOnly))
        return std::nullopt;
    std::optional<MeshLoadResult> result = decode(entry, sourceKey(file, normals));
    if (!result) {
        entry.remove(); // stale or corrupt: never trusted, never read again
        return std::nullopt;
    }
    result->stats.creaseAngleDeg = normals.creaseAngleDeg;
    result->stats.fromCache = true;
    return result;
}

void MeshCache::write(const QString &file, const NormalOptions &normals,
                      const MeshLoadResult &result)
{
    if (!enabled() || !result.mesh || !QDir().mkpath(directory()))
        return;
    QSaveFile entry(entryPath(file, normals));
    if (!entry.open(QIODevice::WriteOnly))
        return;
    if (encode(entry, sourceKey(file, normals), result))
        entry.commit();
    else
        entry.cancelWriting();
}

void MeshCache::adopt(const QString &entryFile, const QString &file, const NormalOptions &normals)
{
    if (!enabled() || !QDir().mkpath(directory())) {
        QFile::remove(entryFile);
        return;
    }
    const QString target = entryPath(file, normals);
    // rename(2) replaces atomically; QFile::rename would refuse an existing target.
    if (std::rename(QFile::encodeName(entryFile).constData(), QFile::encodeName(target).constData())
        != 0)
        QFile::remove(entryFile); // another file system: the next open parses again
}

} // namespace phonglab
