#include "BrowserPipe.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonDocument>
#include <QStandardPaths>

#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace phonglab {

struct BrowserPipeWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::BrowserPipe)
};

namespace {

void closeFd(int &fd)
{
    if (fd >= 0)
        ::close(fd);
    fd = -1;
}

Result<> makePipes(int toBrowser[2], int fromBrowser[2])
{
    if (::pipe2(toBrowser, O_CLOEXEC) != 0)
        return fail(BrowserPipeWords::tr("cannot make a pipe to the browser"));
    if (::pipe2(fromBrowser, O_CLOEXEC) != 0) {
        ::close(toBrowser[0]);
        ::close(toBrowser[1]);
        return fail(BrowserPipeWords::tr("cannot make a pipe to the browser"));
    }
    return {};
}

// The pipe's ends must not be fds 3 or 4 themselves: the dup2 in the
// spawn would overwrite one with the other.
void moveAboveFd4(int *toBrowserRead, int *fromBrowserWrite)
{
    for (int *fd : {toBrowserRead, fromBrowserWrite})
        if (*fd <= 4) {
            const int high = ::fcntl(*fd, F_DUPFD_CLOEXEC, 10);
            ::close(*fd);
            *fd = high;
        }
}

QList<QByteArray> argumentBytes(const QString &program, const QStringList &arguments)
{
    QList<QByteArray> argv8{program.toLocal8Bit()};
    for (const QString &a : arguments + QStringList{QStringLiteral("--remote-debugging-pipe")})
        argv8.push_back(a.toLocal8Bit());
    return argv8;
}

// The environment with the caller's changes: the browser's home and
// caches go where the run may write.
QList<QByteArray> environmentBytes(const QMap<QString, QString> &environment)
{
    QList<QByteArray> env8;
    for (char **e = environ; *e; ++e) {
        const QByteArray entry(*e);
        const QByteArray name = entry.left(entry.indexOf('='));
        if (!environment.contains(QString::fromLocal8Bit(name)))
            env8.push_back(entry);
    }
    for (auto it = environment.cbegin(); it != environment.cend(); ++it)
        env8.push_back((it.key() + QLatin1Char('=') + it.value()).toLocal8Bit());
    return env8;
}

// The char* array execve wants, pointing into `strings` (which must outlive
// it), ended by a null pointer.
std::vector<char *> nullTerminated(QList<QByteArray> &strings)
{
    std::vector<char *> pointers;
    for (QByteArray &s : strings)
        pointers.push_back(s.data());
    pointers.push_back(nullptr);
    return pointers;
}

} // namespace

BrowserPipe::~BrowserPipe()
{
    stop();
}

QString BrowserPipe::executable()
{
    // Another browser binary, or none ("" where no browser should be found).
    if (qEnvironmentVariableIsSet("PHONGLAB_CHROMIUM")) {
        const QString path = qEnvironmentVariable("PHONGLAB_CHROMIUM");
        return QFileInfo(path).isExecutable() ? path : QString();
    }
    for (const QString &path : {QStringLiteral("/usr/lib/chromium/chromium"),
                                QStandardPaths::findExecutable(QStringLiteral("chromium"))})
        if (!path.isEmpty() && QFileInfo(path).isExecutable())
            return path;
    return {};
}

Result<> BrowserPipe::start(const QString &program, const QStringList &arguments,
                            const QMap<QString, QString> &environment, const QString &logFile,
                            qint64 timeLimitMs)
{
    m_clock.start();
    m_total.start();
    m_limitMs = timeLimitMs;
    int toBrowser[2];
    int fromBrowser[2];
    if (Result<> made = makePipes(toBrowser, fromBrowser); !made)
        return made;
    moveAboveFd4(&toBrowser[0], &fromBrowser[1]);
    QList<QByteArray> argv8 = argumentBytes(program, arguments);
    const std::vector<char *> argv = nullTerminated(argv8);
    const QByteArray log = logFile.toLocal8Bit();
    QList<QByteArray> env8 = environmentBytes(environment);
    const std::vector<char *> envp = nullTerminated(env8);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, log.constData(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0600);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    // dup2 clears close-on-exec on the copies the browser keeps.
    posix_spawn_file_actions_adddup2(&actions, toBrowser[0], 3);
    posix_spawn_file_actions_adddup2(&actions, fromBrowser[1], 4);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);
    const int spawned =
        ::posix_spawn(&m_pid, argv[0], &actions, &attributes, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    ::close(toBrowser[0]);
    ::close(fromBrowser[1]);
    m_toBrowser = toBrowser[1];
    m_fromBrowser = fromBrowser[0];
    if (spawned != 0) {
        m_pid = -1;
        stop();
        return fail(BrowserPipeWords::tr("cannot start %1: %2")
                        .arg(program, QString::fromLocal8Bit(strerror(spawned))));
    }
    ::signal(SIGPIPE, SIG_IGN); // a browser gone is an error of write(), not a signal
    return {};
}

void BrowserPipe::restartTimeLimit(qint64 limitMs)
{
    m_pageTime = true;
    m_clock.start();
    m_limitMs = limitMs;
}

void BrowserPipe::stop()
{
    closeFd(m_toBrowser);
    closeFd(m_fromBrowser);
    if (m_pid > 0) {
        ::kill(-m_pid, SIGKILL);
        ::waitpid(m_pid, nullptr, 0);
    }
    m_pid = -1;
}

QString BrowserPipe::timeLimitMessage() const
{
    if (!m_pageTime)
        return BrowserPipeWords::tr("the browser did not start within %1 s")
            .arg(m_limitMs / 1000.0, 0, 'g', 3);
    return BrowserPipeWords::tr("the page did not finish within %1 s (a script that never "
                                "ends, or a page that waits for something)")
        .arg(m_limitMs / 1000.0, 0, 'g', 3);
}

int BrowserPipe::sendMessage(const QString &method, const QJsonObject &params,
                             const QString &session)
{
    const int id = m_nextId++;
    QJsonObject message{{QStringLiteral("id"), id}, {QStringLiteral("method"), method}};
    if (!params.isEmpty())
        message.insert(QStringLiteral("params"), params);
    if (!session.isEmpty())
        message.insert(QStringLiteral("sessionId"), session);
    QByteArray bytes = QJsonDocument(message).toJson(QJsonDocument::Compact);
    bytes.append('\0');
    qsizetype written = 0;
    while (written < bytes.size() && m_toBrowser >= 0) {
        const ssize_t n = ::write(m_toBrowser, bytes.constData() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        written += n;
    }
    return id;
}

void BrowserPipe::send(const QString &method, const QJsonObject &params, const QString &session)
{
    sendMessage(method, params, session);
}

Result<> BrowserPipe::readMore()
{
    if (m_fromBrowser < 0)
        return fail(BrowserPipeWords::tr("the browser went away"));
    const qint64 left = m_limitMs - m_clock.elapsed();
    if (left <= 0)
        return fail(timeLimitMessage());
    if (cancelled && cancelled())
        return fail(BrowserPipeWords::tr("cancelled"));
    pollfd fd{m_fromBrowser, POLLIN, 0};
    const int ready = ::poll(&fd, 1, int(std::min<qint64>(left, 100)));
    if (ready < 0 && errno == EINTR)
        return {};
    if (ready <= 0)
        return {};
    char buffer[65536];
    const ssize_t n = ::read(m_fromBrowser, buffer, sizeof buffer);
    if (n <= 0) {
        closeFd(m_fromBrowser);
        return fail(BrowserPipeWords::tr("the browser went away"));
    }
    m_pending.append(buffer, n);
    qsizetype end;
    while ((end = m_pending.indexOf('\0')) >= 0) {
        m_messages.push_back(QJsonDocument::fromJson(m_pending.left(end)).object());
        m_pending.remove(0, end + 1);
    }
    return {};
}

Result<QJsonObject> BrowserPipe::nextMessage()
{
    while (m_messages.empty())
        if (const Result<> read = readMore(); !read)
            return fail(read.error());
    QJsonObject message = std::move(m_messages.front());
    m_messages.pop_front();
    return message;
}

Result<QJsonObject> BrowserPipe::call(const QString &method, const QJsonObject &params,
                                      const QString &session)
{
    const int id = sendMessage(method, params, session);
    for (;;) {
        Result<QJsonObject> message = nextMessage();
        if (!message)
            return message;
        if (message->contains(QStringLiteral("method"))) {
            if (onEvent)
                onEvent(message->value(QStringLiteral("method")).toString(),
                        message->value(QStringLiteral("params")).toObject(),
                        message->value(QStringLiteral("sessionId")).toString());
            continue;
        }
        if (message->value(QStringLiteral("id")).toInt() != id)
            continue; // the answer to a command sent without waiting
        if (message->contains(QStringLiteral("error")))
            return fail(QStringLiteral("%1: %2").arg(method,
                                                     message->value(QStringLiteral("error"))
                                                         .toObject()
                                                         .value(QStringLiteral("message"))
                                                         .toString()));
        return message->value(QStringLiteral("result")).toObject();
    }
}

Result<> BrowserPipe::waitUntil(const std::function<bool()> &done)
{
    while (!done()) {
        Result<QJsonObject> message = nextMessage();
        if (!message)
            return fail(message.error());
        if (message->contains(QStringLiteral("method")) && onEvent)
            onEvent(message->value(QStringLiteral("method")).toString(),
                    message->value(QStringLiteral("params")).toObject(),
                    message->value(QStringLiteral("sessionId")).toString());
    }
    return {};
}

} // namespace phonglab
