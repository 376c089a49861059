#pragma once

namespace phonglab {

// The share of the processor the window's check runs with. Not idle
// priority: under SCHED_IDLE a student's busy laptop (their own WebGL page
// in a browser, a video call, a build) left the check no time at all
// (2 min 38 s for a verdict beside one compile). A positive nice value
// instead: the window and a mesh load (nice 0) still come first, and the
// check gets a real share beside any busy program. At nice 4 a thread
// weighs 423 against a busy program's 1024 (the kernel's CFS weights): on a
// core shared with one, about 29 % of it.
inline constexpr int kCheckNice = 4;

// Puts the calling thread (and the threads it starts later, which inherit
// it: the ray casting's) at kCheckNice, where it runs nicer than that now.
// Never back: a process without CAP_SYS_NICE cannot lower a nice value, so
// the check's pool keeps its one thread for checks alone. Elsewhere than
// Linux, QThread's low priority.
void runAtCheckPriority();

} // namespace phonglab
