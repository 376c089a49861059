#include "CurrentContext.h"

#include "Viewport.h"

namespace phonglab {

CurrentContext::CurrentContext(Viewport &viewport)
    : m_viewport(viewport)
{
    m_viewport.glContext().takeBackContext();
    m_viewport.makeCurrent();
}

CurrentContext::~CurrentContext()
{
    m_viewport.doneCurrent();
}

} // namespace phonglab
