#include "LentRenderer.h"

#include "render/draw/FrameEstimate.h"
#include "render/draw/Renderer.h"

namespace phonglab {

LentRenderer::LentRenderer(Renderer *renderer)
    : m_renderer(renderer)
{
}

void LentRenderer::exchangeProgram(GlProgram &program) const
{
    m_renderer->exchangeProgram(program);
}

double LentRenderer::trialFrameMs(const LentContext &loan, const QSize &pixels,
                                  double limitMs) const
{
    return phonglab::trialFrameMs(*m_renderer, loan, pixels, limitMs);
}

} // namespace phonglab
