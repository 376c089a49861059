#include "MeshFiles.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

namespace phonglab::test {

TriMesh referenceTetra()
{
    TriMesh m;
    const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0});
    const auto c = m.add_vertex({0, 1, 0}), d = m.add_vertex({0, 0, 1});
    m.add_face(a, c, b);
    m.add_face(a, b, d);
    m.add_face(a, d, c);
    m.add_face(b, c, d);
    return m;
}

// OpenMesh's writers chat on omlog and switch it back on when done.
bool writeMesh(const TriMesh &m, const QString &path, OpenMesh::IO::Options options)
{
    omlog().disable();
    const bool ok = OpenMesh::IO::write_mesh(m, path.toStdString(), options);
    omlog().disable();
    return ok;
}

QString writeTetra(const QTemporaryDir &dir, const QString &name, bool binary)
{
    const QString path = dir.filePath(name);
    OpenMesh::IO::Options options;
    if (binary)
        options += OpenMesh::IO::Options::Binary;
    return writeMesh(referenceTetra(), path, options) ? path : QString();
}

void writeBytes(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QCOMPARE(f.write(bytes), bytes.size());
}

QByteArray readBytes(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace phonglab::test
