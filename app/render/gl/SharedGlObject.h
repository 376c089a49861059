#pragma once
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPointer>
#include <utility>

namespace phonglab {

// Owns the name of one GL object that a share group holds in common (a
// program or a shader) and frees it when the owner goes: move-only, so that
// exactly one holder frees each name.
//
// Any context of the group may free such an object, which is what lets a
// program change hands between threads: the build thread drops a program
// nobody wants with its own context current, the viewport frees its old one
// with the viewport's. When no context of the group is current the name is
// left to the group, which frees its objects with its last context. It is
// never freed through a context of another group, where the same number
// names something else.
template <void (QOpenGLFunctions::*Free)(GLuint)> class SharedGlObject
{
public:
    SharedGlObject() = default;
    // Takes `id`, just made in the current context (0: owns nothing).
    explicit SharedGlObject(GLuint id)
        : m_id(id)
    {
        if (QOpenGLContext *current = QOpenGLContext::currentContext(); id && current)
            m_group = current->shareGroup();
    }
    SharedGlObject(SharedGlObject &&other) noexcept
        : m_id(std::exchange(other.m_id, 0))
        , m_group(std::move(other.m_group))
    {
    }
    SharedGlObject &operator=(SharedGlObject &&other) noexcept
    {
        if (this != &other) {
            reset();
            m_id = std::exchange(other.m_id, 0);
            m_group = std::move(other.m_group);
        }
        return *this;
    }
    SharedGlObject(const SharedGlObject &) = delete;
    SharedGlObject &operator=(const SharedGlObject &) = delete;
    ~SharedGlObject() { reset(); }

    // The name, for GL calls; the object stays owned here.
    GLuint id() const { return m_id; }
    explicit operator bool() const { return m_id != 0; }

    void reset()
    {
        QOpenGLContext *current = QOpenGLContext::currentContext();
        if (m_id && current && m_group && current->shareGroup() == m_group)
            (current->functions()->*Free)(m_id);
        m_id = 0;
        m_group.clear();
    }

private:
    GLuint m_id = 0;
    QPointer<QOpenGLContextGroup> m_group;
};

using GlProgram = SharedGlObject<&QOpenGLFunctions::glDeleteProgram>;
using GlShader = SharedGlObject<&QOpenGLFunctions::glDeleteShader>;

} // namespace phonglab
