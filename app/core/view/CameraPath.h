#pragma once
#include "Camera.h"
#include "DepthRange.h"
#include "core/support/Result.h"

#include <QByteArray>
#include <QString>
#include <vector>

namespace phonglab {

// A scripted camera for `phonglab bench --path`: one camera per frame.
struct CameraPath {
    QString name; // "orbit", "dolly", or the keyframe file's base name
    std::vector<Camera> cameras;
};

inline constexpr int kDefaultPathFrames = 24;

// One turn around the target about the camera's up axis, starting where
// `start` is, while the distance grows from the start's to 2.5 times it: an
// orbit that also moves out.
CameraPath orbitPath(const Camera &start, int frames = kDefaultPathFrames);

// Along the line from the target through the start's eye: from just outside
// `scene` (1.25 bounding radii from its centre, or a tenth of the start's
// distance if that is closer) to 32 times the start's distance (the far
// plane moved out with it), the
// distances spaced evenly in their logarithm so that the far frames are as
// many as the near ones.
CameraPath dollyPath(const Camera &start, const BoundingSphere &scene,
                     int frames = kDefaultPathFrames);

// Keyframes from a JSON file:
//   {"frames": 48, "keyframes": [{"eye": [x, y, z], "target": [x, y, z],
//                                 "up": [x, y, z], "fov_deg": 45}, ...]}
// At least two keyframes, each with "eye" (and the other fields optional:
// the previous keyframe's, the first one's from `start`); "frames" from 2 to
// 10000 (default kDefaultPathFrames), spread evenly over the keyframes'
// parameter, each keyframe interpolated linearly to the next. Errors name
// the field: "keyframes[1].eye: expected 3 numbers".
Result<CameraPath> parseCameraPath(const QByteArray &json, const Camera &start,
                                   const QString &name);
Result<CameraPath> loadCameraPath(const QString &file, const Camera &start);

} // namespace phonglab
