#pragma once
#include "SceneLoadJob.h"

#include <QStringList>

namespace phonglab {

// The loads the window starts. Each sets what to load, its label and how to
// finish; `shown` (the window's own bookkeeping) is left to the caller.

// A parsed scene file, shown as it is.
SceneLoadRequest sceneFileRequest(const QString &path, const Scene &scene);
// Mesh files replacing `current`'s objects, fitted side by side once their
// bounds are known (see MeshPlacement.h).
SceneLoadRequest meshFilesRequest(const Scene &current, const QStringList &paths);
// Object `objectIndex` of `current` with other normals (a valid index).
SceneLoadRequest normalsRequest(const Scene &current, int objectIndex,
                                const NormalOptions &options);
// `current` with every object at `detail` (fraction of its full triangles)
// and `method` shading: what Fit to budget applies.
SceneLoadRequest fitRequest(const Scene &current, ShadingMethod method, double detail);
// Every object to "detail": "auto" (the levels are built by the load, off
// the GUI thread), or back to full detail.
SceneLoadRequest autoDetailRequest(const Scene &current, bool on);

} // namespace phonglab
