#include "GradedChild.h"

#include "core/support/Language.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <new>
#include <sys/prctl.h>
#include <unistd.h>
#include <vector>

namespace phonglab::cli {

namespace {

constexpr int kPollMs = 25; // how late a limit can be noticed

QString signalName(int signal)
{
    const char *abbrev = sigabbrev_np(signal);
    return abbrev ? QStringLiteral("SIG") + QString::fromLatin1(abbrev) : QStringLiteral("unknown");
}

// The answer is the last line of stdout that is a JSON object: the driver
// may print before it.
QJsonObject answerIn(const QByteArray &stdoutText)
{
    const QList<QByteArray> lines = stdoutText.trimmed().split('\n');
    for (auto it = lines.rbegin(); it != lines.rend(); ++it) {
        const QJsonDocument doc = QJsonDocument::fromJson(it->trimmed());
        if (doc.isObject())
            return doc.object();
    }
    return {};
}

QString lastLine(const QByteArray &text)
{
    const QList<QByteArray> lines = text.trimmed().split('\n');
    return lines.isEmpty() ? QString() : QString::fromUtf8(lines.back()).trimmed().left(300);
}

[[noreturn]] void outOfMemory()
{
    ::_exit(kGradedChildOutOfMemory); // nothing allocated on the way out
}

} // namespace

GradedChild::GradedChild(const QString &executable, const QStringList &arguments,
                         const GradedChildLimits &limits, QObject *parent)
    : QObject(parent)
    , m_executable(executable)
    , m_arguments(arguments)
    , m_limits(limits)
{
    m_poll.setInterval(kPollMs);
    connect(&m_poll, &QTimer::timeout, this, &GradedChild::poll);
    connect(&m_process, &QProcess::finished, this, &GradedChild::onFinished);
    connect(&m_process, &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
        if (error == QProcess::FailedToStart)
            finish({GradedChildEnd::Kind::Crashed,
                    {},
                    GradedChild::tr("the check could not start: %1").arg(m_process.errorString()),
                    0.0});
    });
}

void GradedChild::start()
{
    m_clock.start();
    // The child's sentences go into the report: in this run's language.
    m_process.start(m_executable,
                    m_arguments + QStringList{QStringLiteral("--lang"), currentLanguage()});
    m_poll.start();
}

qint64 GradedChild::residentBytes() const
{
    QFile statm(QStringLiteral("/proc/%1/statm").arg(m_process.processId()));
    if (!statm.open(QIODevice::ReadOnly))
        return 0;
    const QList<QByteArray> fields = statm.readAll().split(' ');
    return fields.size() > 1 ? fields[1].toLongLong() * ::sysconf(_SC_PAGESIZE) : 0;
}

void GradedChild::poll()
{
    if (m_ended || m_process.state() != QProcess::Running)
        return;
    // A child that ended while this process was busy is answered, not
    // blamed for the delay.
    if (m_process.waitForFinished(0))
        return;
    const double seconds = m_clock.elapsed() / 1000.0;
    if (m_clock.elapsed() > m_limits.wallClockMs) {
        m_process.kill();
        finish({GradedChildEnd::Kind::TimedOut,
                {},
                GradedChild::tr("ran past the %1 s limit and was stopped (a loop that runs too "
                                "long, or a frame the GPU cannot finish)")
                    .arg(sentenceNumber(m_limits.wallClockMs / 1000.0)),
                seconds});
    } else if (const qint64 bytes = residentBytes(); bytes > m_limits.memoryBytes) {
        m_process.kill();
        finish({GradedChildEnd::Kind::Crashed,
                {},
                GradedChild::tr("used more than %1 MiB of memory and was stopped")
                    .arg(m_limits.memoryBytes / (1024 * 1024)),
                seconds});
    }
}

void GradedChild::onFinished(int exitCode, QProcess::ExitStatus status)
{
    const double seconds = m_clock.elapsed() / 1000.0;
    if (status == QProcess::CrashExit) {
        QString message = GradedChild::tr("the check crashed with signal %1 (%2)")
                              .arg(exitCode)
                              .arg(signalName(exitCode));
        if (const QString said = lastLine(m_process.readAllStandardError()); !said.isEmpty())
            message += GradedChild::tr("; it said: ") + said;
        finish({GradedChildEnd::Kind::Crashed, {}, message, seconds});
        return;
    }
    if (exitCode == kGradedChildOutOfMemory) {
        finish({GradedChildEnd::Kind::Crashed,
                {},
                GradedChild::tr("the check ran out of memory"),
                seconds});
        return;
    }
    const QJsonObject answer = answerIn(m_process.readAllStandardOutput());
    if (answer.isEmpty()) {
        QString message =
            GradedChild::tr("the check exited with status %1 without an answer").arg(exitCode);
        if (const QString said = lastLine(m_process.readAllStandardError()); !said.isEmpty())
            message += GradedChild::tr("; it said: ") + said;
        finish({GradedChildEnd::Kind::Crashed, {}, message, seconds});
        return;
    }
    finish({GradedChildEnd::Kind::Answered, answer, QString(), seconds});
}

void GradedChild::finish(GradedChildEnd end)
{
    if (m_ended)
        return;
    m_ended = true;
    m_poll.stop();
    if (m_process.state() != QProcess::NotRunning) {
        m_process.kill();
        m_process.waitForFinished(1000);
    }
    emit ended(end);
}

void injectGradedChildFault(const QString &fragmentPath)
{
    if (qgetenv("PHONGLAB_GRADE_FAULTS") != "1" || fragmentPath.isEmpty())
        return;
    QFile file(fragmentPath);
    if (!file.open(QIODevice::ReadOnly))
        return;
    const QByteArray text = file.read(1 << 20);
    if (text.contains("PHONGLAB_FAULT: crash")) {
        std::signal(SIGSEGV, SIG_DFL); // not a sanitizer's report and exit status 1
        std::raise(SIGSEGV);
    } else if (text.contains("PHONGLAB_FAULT: oom")) {
        constexpr std::size_t kBlock = 64u << 20;
        // Kept where the program can reach them: an allocation nobody reads
        // may be dropped with its memset (clang does), and the child would
        // sleep here at its first size until the timeout.
        static std::vector<char *> kept;
        for (;;) {
            char *block = static_cast<char *>(std::malloc(kBlock)); // never freed: on purpose
            if (!block)
                ::_exit(kGradedChildOutOfMemory);
            std::memset(block, 1, kBlock); // touched: resident
            kept.push_back(block);
            ::usleep(10'000);
        }
    } else if (text.contains("PHONGLAB_FAULT: hang")) {
        for (;;)
            ::pause();
    }
}

void beAGradedChild()
{
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    std::set_new_handler(outOfMemory);
}

} // namespace phonglab::cli
