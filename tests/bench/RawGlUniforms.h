#pragma once
#include "core/Scene.h"

#include <QSize>
#include <QtGui/qopengl.h>

namespace phonglab::bench {

// The shipped Phong program's uniforms for one object, set with plain GL
// calls (glGetUniformLocation + glUniform*), as a program without Qt's
// wrappers would: what the raw-GL baselines upload per draw.
void setPhongUniforms(GLuint program, const Scene &scene, const SceneObject &object,
                      const QSize &size);

} // namespace phonglab::bench
