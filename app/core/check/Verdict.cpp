#include "Verdict.h"

namespace phonglab {

QString verdictName(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Pass: return QStringLiteral("pass");
    case Verdict::Fail: return QStringLiteral("fail");
    case Verdict::Error: return QStringLiteral("error");
    case Verdict::Timeout: return QStringLiteral("timeout");
    case Verdict::Crash: return QStringLiteral("crash");
    }
    return QStringLiteral("error");
}

} // namespace phonglab
