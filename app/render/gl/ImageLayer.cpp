#include "ImageLayer.h"

#include <QOpenGLContext>
#include <QtDebug>

namespace phonglab {

namespace {

// The whole viewport from gl_VertexID: no vertex buffer to keep. The image's
// first row is its top; texture rows start at the bottom, hence 1 - y.
constexpr const char *kVertexShader = R"(#version 330 core
out vec2 uv;
void main() {
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    uv = vec2(corner.x, 1.0 - corner.y);
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char *kFragmentShader = R"(#version 330 core
uniform sampler2D image;
in vec2 uv;
out vec4 color;
void main() { color = texture(image, uv); }
)";

} // namespace

bool ImageLayer::create()
{
    initializeOpenGLFunctions();
    const auto compile = [this](GLenum type, const char *text) {
        const GLuint shader = glCreateShader(type);
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        return shader;
    };
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    m_program = glCreateProgram();
    glAttachShader(m_program, vs);
    glAttachShader(m_program, fs);
    glLinkProgram(m_program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint linked = GL_FALSE;
    glGetProgramiv(m_program, GL_LINK_STATUS, &linked);
    if (!linked) {
        qWarning("phonglab: the program that draws widgets over the viewport does not link");
        destroy();
        m_failed = true;
        return false;
    }
    glGenVertexArrays(1, &m_vao);
    glGenTextures(1, &m_texture);
    glBindTexture(GL_TEXTURE_2D, m_texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return true;
}

void ImageLayer::draw(const QImage &image, const QSize &pixelSize)
{
    if (m_failed || image.isNull() || pixelSize.isEmpty() || (!m_program && !create()))
        return;
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m_texture);
    if (image.cacheKey() != m_uploadedKey) {
        // GL wants RGBA bytes; QPainter's premultiplied ARGB32 is BGRA in memory.
        const QImage upload = image.format() == QImage::Format_RGBA8888_Premultiplied
            ? image
            : image.convertToFormat(QImage::Format_RGBA8888_Premultiplied);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, upload.bytesPerLine() / 4);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, upload.width(), upload.height(), 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, upload.constBits());
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        m_uploadedKey = image.cacheKey();
    }
    glViewport(0, 0, pixelSize.width(), pixelSize.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA); // premultiplied
    glUseProgram(m_program);
    glUniform1i(glGetUniformLocation(m_program, "image"), 0);
    glBindVertexArray(m_vao);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_BLEND);
}

void ImageLayer::destroy()
{
    if (!QOpenGLContext::currentContext())
        return;
    if (m_program) {
        glDeleteProgram(m_program);
        glDeleteVertexArrays(1, &m_vao);
        glDeleteTextures(1, &m_texture);
    }
    m_program = m_vao = m_texture = 0;
    m_uploadedKey = 0;
}

} // namespace phonglab
