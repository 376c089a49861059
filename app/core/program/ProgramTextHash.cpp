#include "ProgramTextHash.h"

#include <QCryptographicHash>

namespace phonglab {

QByteArray programTextHash(const QByteArray &vertex, const QByteArray &fragment)
{
    QCryptographicHash hash(QCryptographicHash::Sha1);
    hash.addData(QByteArray::number(vertex.size()) + ':');
    hash.addData(vertex);
    hash.addData(QByteArray::number(fragment.size()) + ':');
    hash.addData(fragment);
    return hash.result().toHex();
}

} // namespace phonglab
