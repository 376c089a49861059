#pragma once
#include <QByteArray>

namespace phonglab {

// What identifies a program's text: a pair of stage texts as a hex SHA-1,
// the stages kept apart so that moving text from one to the other changes
// it. The live build skips a text already built by it, and the recovery
// journal names the program that was running with it.
QByteArray programTextHash(const QByteArray &vertex, const QByteArray &fragment);

} // namespace phonglab
