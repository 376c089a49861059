#include "ProgressLine.h"

#include <cstdio>
#include <unistd.h>

namespace phonglab::cli {

ProgressLine::ProgressLine(Elsewhere elsewhere)
    : m_tty(isatty(fileno(stderr)) != 0)
    , m_elsewhere(elsewhere)
{
}

void ProgressLine::show(const QString &text)
{
    if (m_tty)
        std::fprintf(stderr, "\r\033[K%s", text.toLocal8Bit().constData());
    else if (m_elsewhere == Elsewhere::Lines)
        std::fprintf(stderr, "%s\n", text.toLocal8Bit().constData());
    std::fflush(stderr);
}

void ProgressLine::clear()
{
    if (m_tty) {
        std::fprintf(stderr, "\r\033[K");
        std::fflush(stderr);
    }
}

} // namespace phonglab::cli
