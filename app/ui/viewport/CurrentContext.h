#pragma once

namespace phonglab {

class Viewport;

// The viewport's GL context current on this thread for one scope: taken back
// first if it is lent (ViewContext::lendContext), released at the end. The one
// way code outside a frame uses that context, so no caller can forget the
// loan or leave the context current.
class CurrentContext
{
public:
    explicit CurrentContext(Viewport &viewport);
    ~CurrentContext();
    CurrentContext(const CurrentContext &) = delete;
    CurrentContext &operator=(const CurrentContext &) = delete;

private:
    Viewport &m_viewport;
};

} // namespace phonglab
