#include "MeshLoader.h"

#include "BuiltinMeshes.h"

namespace phonglab {

MeshLoadResult loadMesh(const QString &spec)
{
    MeshLoadResult result;
    if (isBuiltinMeshSpec(spec)) {
        result.mesh = builtinMesh(spec);
        if (!result.mesh)
            result.error = QStringLiteral("%1: unknown builtin mesh (known: builtin:sphere, builtin:torus)").arg(spec);
        return result;
    }
    // Mesh files arrive with the OpenMesh importer; until then say so plainly.
    result.error = QStringLiteral("%1: mesh files cannot be loaded yet; use builtin:sphere or builtin:torus").arg(spec);
    return result;
}

} // namespace phonglab
