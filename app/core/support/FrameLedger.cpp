#include "FrameLedger.h"

#include <utility>

namespace phonglab {

bool FrameLedger::mayDraw()
{
    if (m_held)
        ++m_refused;
    return !m_held;
}

bool FrameLedger::book(qint64 atNs, double drawMs, bool fromLoan)
{
    m_times.add(atNs, drawMs);
    ++m_rendered;
    if (fromLoan)
        ++m_fromLoans;
    if (m_held || drawMs <= kHoldFramesAfterMs)
        return false;
    m_held = true;
    return true;
}

bool FrameLedger::resume()
{
    return std::exchange(m_held, false);
}

} // namespace phonglab
