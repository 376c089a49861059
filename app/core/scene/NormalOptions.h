#pragma once
#include <QString>
#include <QStringList>
#include <optional>

namespace phonglab {

// How a mesh gets its normals. Auto: the file's normals when it has them,
// else computed angle-weighted. The other methods always compute, ignoring
// any normals in the file.
enum class NormalMethod {
    Auto,
    Flat,         // the face's own normal at every corner
    Average,      // unweighted mean of the adjacent face normals
    AreaWeighted, // face normals weighted by face area
    AngleWeighted // face normals weighted by the corner angle (default)
};

struct NormalOptions {
    NormalMethod method = NormalMethod::Auto;
    // When set, faces meeting at a dihedral angle above this many degrees
    // do not share normals (a crease): the vertex is split there.
    std::optional<double> creaseAngleDeg;

    bool operator==(const NormalOptions &) const = default;
};

// Names as written in scene files and on the command line:
// "auto", "flat", "average", "area", "angle".
QString normalMethodName(NormalMethod method);
std::optional<NormalMethod> normalMethodFromName(const QString &name);
QStringList normalMethodNames();

} // namespace phonglab
