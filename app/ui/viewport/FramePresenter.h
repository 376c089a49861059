#pragma once
#include "render/gl/LentContext.h"

#include <QObject>
#include <QThread>
#include <chrono>

namespace phonglab {

// Finishes and presents the viewport's frames on a thread of its own. The
// GUI thread only records a frame's commands and lends the context here
// (ContextLender); the wait for the rasteriser (on llvmpipe most of a frame)
// and swapBuffers happen on this thread, so typing goes on meanwhile, the
// way Qt Quick's threaded render loop presents. Each frame ends in
// presented(), queued to the owner's thread, once the context is back there.
class FramePresenter : public QObject
{
    Q_OBJECT

public:
    explicit FramePresenter(QObject *parent = nullptr);
    ~FramePresenter() override;

    QThread *presenterThread() { return &m_thread; }
    // On the owner's thread, with `lent` lent to presenterThread(): waits
    // for the frame (glFinish), swaps and gives the context back to `owner`.
    // `started` is when the frame's first GL call was made.
    // `loan` comes back with presented(), so that a late signal ends no newer loan.
    void present(quint64 loan, LentContext lent, QThread *owner,
                 std::chrono::steady_clock::time_point started);

signals:
    // `drawMs`: from the frame's first GL call to glFinish; `swappedNs`:
    // when swapBuffers returned (steady_clock). `ok` false when the context
    // could not be made current here (then nothing was shown).
    void presented(quint64 loan, double drawMs, qint64 swappedNs, bool ok);

private:
    QThread m_thread;
    QObject m_worker; // lives in m_thread; present()'s work is queued to it
};

} // namespace phonglab
