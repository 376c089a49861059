#include "CheckPriority.h"

#include <QThread>

#ifdef Q_OS_LINUX
#include <cerrno>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace phonglab {

void runAtCheckPriority()
{
#ifdef Q_OS_LINUX
    // setpriority() with a thread's id sets that thread alone (Linux's
    // nice is per thread); a thread it starts inherits it.
    const id_t thread = id_t(syscall(SYS_gettid));
    // An idle-scheduled thread (an older build's) comes back to the normal
    // policy first: nice means nothing under SCHED_IDLE.
    sched_param normal{};
    if (sched_getscheduler(0) == SCHED_IDLE)
        sched_setscheduler(0, SCHED_OTHER, &normal);
    errno = 0;
    const int now = getpriority(PRIO_PROCESS, thread);
    if (errno == 0 && now < kCheckNice)
        setpriority(PRIO_PROCESS, thread, kCheckNice);
#else
    QThread::currentThread()->setPriority(QThread::LowPriority);
#endif
}

} // namespace phonglab
