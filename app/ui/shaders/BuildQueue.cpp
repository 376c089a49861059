#include "BuildQueue.h"

#include <algorithm>

namespace phonglab {

BuildQueue::BuildQueue(int debounceMs, QObject *parent)
    : QObject(parent)
{
    m_pause.setSingleShot(true);
    m_pause.setInterval(std::max(0, debounceMs));
    connect(&m_pause, &QTimer::timeout, this, &BuildQueue::pauseOver);
}

void BuildQueue::edited()
{
    m_pause.start();
}

void BuildQueue::stopPause()
{
    m_pause.stop();
}

void BuildQueue::wait(Request request)
{
    m_waiting = m_waiting == Request::Always ? Request::Always : request;
}

BuildQueue::Decision BuildQueue::decide(Request request, const QByteArray &hash, Builder builder)
{
    if (builder == Builder::NoGl) {
        wait(request);
        return Decision::Wait;
    }
    if (request == Request::NewText && hash == m_lastBuilt)
        return Decision::Skip;
    if (builder == Builder::Busy) {
        wait(request);
        return Decision::Wait;
    }
    return Decision::Build;
}

} // namespace phonglab
