#pragma once
#include "core/program/UniformAnnotations.h"
#include "core/program/UniformOwner.h"
#include "render/program/UniformSnapshot.h"

#include <QWidget>

namespace phonglab {

// What the Uniforms dock knows about one uniform element ("gain", "Id[2]").
struct UniformRowSpec {
    QString element;  // as glGetUniformLocation takes it
    QString baseName; // without the element index
    GLenum type = 0;
    UniformOwner owner = UniformOwner::User;
    const UniformDeclaration *declaration = nullptr; // its annotations, if the text declares it
    const UniformValue *value = nullptr;             // its current value, if it could be read
};

// The editor for one uniform element: UniformFloatRow, UniformVectorRow,
// UniformIntRow, UniformBoolRow, or a read-only QLabel for other types
// (matrices, samplers). Shows `spec.value`; disabled with a tooltip saying
// who sets it when the user does not own it. Connects nothing.
QWidget *createUniformRow(const UniformRowSpec &spec, QWidget *parent);

// Shows `value` in a row made by createUniformRow, without edited().
void showUniformValue(QWidget *row, const UniformValue &value);

// vec3s the renderer treats as colours (reflection and intensity).
bool isColorUniformName(const QString &baseName);

} // namespace phonglab
