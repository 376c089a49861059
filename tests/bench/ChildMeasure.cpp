#include "ChildMeasure.h"

#include <chrono>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace phonglab::bench {

ChildSample measureInChild(const std::function<long long()> &work)
{
    int fds[2];
    if (pipe(fds) != 0)
        return {};
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        const auto start = std::chrono::steady_clock::now();
        const long long result = work();
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        rusage self{}, children{};
        getrusage(RUSAGE_SELF, &self);
        getrusage(RUSAGE_CHILDREN, &children);
        const ChildSample s{ms, self.ru_maxrss / 1024.0, children.ru_maxrss / 1024.0, result};
        (void)!write(fds[1], &s, sizeof s);
        _exit(0);
    }
    close(fds[1]);
    ChildSample s;
    if (read(fds[0], &s, sizeof s) != ssize_t(sizeof s))
        s = ChildSample();
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    return s;
}

} // namespace phonglab::bench
