#pragma once
#include "LentRenderer.h"
#include "render/gl/LentContext.h"

#include <QString>
#include <optional>

class QOpenGLContext;
class QThread;

namespace phonglab {

// The view's GL context as another thread borrows it: the live shader
// build compiles a new program's draw-time variant in this very context,
// off the GUI thread. Handed out by Viewport::glContext().
class ViewContext
{
public:
    // Lends the context to `borrower` (see LentContext). Until
    // takeBackContext() the view does not paint, and anything that needs
    // the context on the GUI thread first waits for it to come back. Waits
    // for a frame being presented first. Refused (nullopt) before GL is up:
    // the caller then does the work itself.
    virtual std::optional<LentContext> lendContext(QThread *borrower) = 0;
    // The renderer as the borrower may use it while the loan lasts.
    virtual LentRenderer lentRenderer() = 0;
    // Waits for a lent context (at most timeoutMs; -1: as long as it takes)
    // and paints again. False if it did not come back in time.
    virtual bool takeBackContext(int timeoutMs = -1) = 0;
    virtual bool isContextLent() const = 0;
    // Null before the view's window was first shown; made current on the
    // GUI thread by CurrentContext only.
    virtual QOpenGLContext *context() const = 0;
    // "OpenGL <version> (<renderer>)", empty before GL is up.
    virtual QString glRendererName() const = 0;

protected:
    ~ViewContext() = default;
};

} // namespace phonglab
