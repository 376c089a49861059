#pragma once
#include <QString>

namespace phonglab::cli {

// A command's progress on stderr: on a terminal one line rewritten in
// place; elsewhere (a log, the Performance dock reading the bench) a line
// per step, or nothing, as the command chooses. The one way `grade` and
// `bench` show how far they are.
class ProgressLine
{
public:
    enum class Elsewhere {
        Lines,  // a line per show()
        Nothing // progress only on a terminal
    };
    explicit ProgressLine(Elsewhere elsewhere);

    void show(const QString &text);
    // Wipes the line on a terminal (before other output, and at the end).
    void clear();
    bool onTerminal() const { return m_tty; }

private:
    bool m_tty = false;
    Elsewhere m_elsewhere = Elsewhere::Lines;
};

} // namespace phonglab::cli
