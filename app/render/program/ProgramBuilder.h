#pragma once
#include "BuildReport.h"
#include "ShaderSource.h"
#include "core/program/CoursePrelude.h"
#include "core/program/ShaderBindings.h"
#include "render/gl/SharedGlObject.h"

#include <QOpenGLExtraFunctions>

namespace phonglab {

// What one build produced. `program` is the linked program, now the
// caller's (empty when the build failed); the timings split the work so that
// benchmarks and the status bar can say where the time went.
struct BuiltProgram {
    GlProgram program;
    BuildReport report;
    qint64 compileNs = 0; // both stages, glCompileShader + status + log
    qint64 linkNs = 0;    // glLinkProgram + status + log

    bool ok() const { return bool(program); }
};

// Compiles and links a program on whatever context is current, through
// glShaderSource directly (not QOpenGLShader) so the driver sees exactly the
// user's lines, plus an optional prologue that #line maps back. Keeps
// nothing: ShaderProgram takes the program on the GUI thread, the build
// thread hands it from its worker context to the viewport's.
class ProgramBuilder : protected QOpenGLExtraFunctions
{
public:
    // The vertex inputs that mean the position and the normal are placed
    // where the meshes feed them (locations 0 and 1; a shader's own layout
    // qualifiers win): by name as core/ShaderBindings reads them, or by
    // `bindings`. Each stage is compiled as the course's page would hand
    // it over (`course`: core/program/CoursePrelude), on the user's own lines.
    BuiltProgram build(const ShaderSource &vertex, const ShaderSource &fragment,
                       const QStringList &defines = {}, const ExplicitBindings &bindings = {},
                       const CourseOptions &course = {});

private:
    bool placeInputs(GLuint program, const ExplicitBindings &bindings, const QString &linkName,
                     BuildReport &result);
    GlShader compileStage(GLenum type, const ShaderSource &source, const QStringList &defines,
                          const CourseOptions &course, BuildReport &result);
    GlProgram link(const GlShader &vertex, const GlShader &fragment, const QString &linkName,
                   BuildReport &result);
    QString infoLog(GLuint object, bool isProgram);

    bool m_initialized = false;
};

} // namespace phonglab
