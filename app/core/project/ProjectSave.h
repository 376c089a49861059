#pragma once
#include "ProjectShader.h"

#include <QByteArray>

namespace phonglab {

// Saving a shader back into the page or script it came from:
// only the shader's bytes change. The text is escaped as its container
// escapes it (a template literal's backslashes, backticks and ${, a
// textarea's & and <); a shader built from several strings is never written
// back, and Save As is the way out.

// `text` as `container` writes it.
QByteArray encodedShaderText(ShaderContainer container, char quote, const QByteArray &text);

// Why a shader cannot be written back where it is (empty: it can), from what
// was read: its container, and whether its bytes are its encoded text.
QString whyNotWritable(const ProjectShader &shader, const QByteArray &file);

// The file's bytes with the shader's replaced by `text`; an error where it
// cannot be written back (with Save As named as the way out).
Result<QByteArray> withShaderText(const QByteArray &file, const ProjectShader &shader,
                                  const QByteArray &text);

} // namespace phonglab
