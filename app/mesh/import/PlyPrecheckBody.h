#pragma once
// Internal to PlyPrecheck*.cpp: a PLY header as PlyPrecheck.cpp reads it,
// and the checks of the body it describes (PlyPrecheckBody.cpp: a binary
// body walked, an ascii one validated value by value).
#include "MeshFilePrecheck.h"

#include <QCoreApplication>
#include <QFile>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct PlyPrecheckWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PlyPrecheck)
};

namespace ply {

struct PlyType {
    int size = 0;
    bool integer = false;
    bool isSigned = false;
};

struct PlyProperty {
    std::string name;
    PlyType type;
    bool isList = false;
    PlyType countType;
};

struct PlyElement {
    std::string name;
    quint64 count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyHeader {
    enum Format {
        Unknown,
        Ascii,
        LittleEndian,
        BigEndian
    } format = Unknown;
    std::vector<PlyElement> elements;
    qint64 bodyOffset = 0;
    std::size_t bodyLine = 1;
};

// Sets check.error where the body is shorter than the header says or a list
// length is negative; warns about bytes after the last element.
void walkBinary(QFile &file, const PlyHeader &h, MeshFilePrecheck &check);
// Sets check.error at the first value that is not what its property's type
// needs; warns about text after the last element.
void validateAscii(std::string_view body, const PlyHeader &h, MeshFilePrecheck &check);

} // namespace ply
} // namespace phonglab
