#pragma once
#include "BuildReport.h"
#include "ShaderSource.h"

#include <QOpenGLExtraFunctions>

namespace phonglab {

// What one build produced. `program` is a linked program object the caller
// now owns (0 when the build failed); the timings split the work so that
// benchmarks and the status bar can say where the time went.
struct BuiltProgram {
    GLuint program = 0;
    BuildReport result;
    qint64 compileNs = 0; // both stages, glCompileShader + status + log
    qint64 linkNs = 0;    // glLinkProgram + status + log

    bool ok() const { return program != 0; }
};

// Compiles and links a program on whatever context is current, through
// glShaderSource directly (not QOpenGLShader) so the driver sees exactly the
// user's lines, plus an optional prologue that #line maps back. Owns nothing:
// ShaderProgram wraps the result on the GUI thread, the background builder
// hands it from its worker context to the viewport's.
class ProgramBuilder : protected QOpenGLExtraFunctions
{
public:
    BuiltProgram build(const ShaderSource &vertex, const ShaderSource &fragment, const QStringList &defines = {});

private:
    GLuint compileStage(GLenum type, const ShaderSource &source, const QStringList &defines, BuildReport &result);
    GLuint link(GLuint vertexShader, GLuint fragmentShader, const QString &linkName, BuildReport &result);
    QString infoLog(GLuint object, bool isProgram);

    bool m_initialized = false;
};

} // namespace phonglab
