#pragma once
#include "core/support/Result.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QJsonObject>
#include <QMap>
#include <QString>
#include <QStringList>

#include <sys/types.h>

#include <deque>
#include <functional>

namespace phonglab {

// Headless Chromium driven over its DevTools protocol on a pipe
// (--remote-debugging-pipe: the browser reads commands on its fd 3 and
// writes answers and events on fd 4, each a JSON text ended by a NUL), so
// no port is opened. The browser runs in a process group of its own, which
// stop() kills whole: its renderer and GPU processes go with it.
//
// Everything waits against one deadline (the run's time limit): a page that
// loops forever in JavaScript or never answers cannot hold the caller.
class BrowserPipe
{
public:
    BrowserPipe() = default;
    ~BrowserPipe();
    BrowserPipe(const BrowserPipe &) = delete;
    BrowserPipe &operator=(const BrowserPipe &) = delete;

    // Debian's chromium binary (not the /usr/bin wrapper script), or empty;
    // $PHONGLAB_CHROMIUM where set (empty or not executable: none).
    static QString executable();

    // Starts `program` with `arguments` (--remote-debugging-pipe added) and
    // this process's environment with `environment` over it; its output
    // goes to `logFile`.
    Result<> start(const QString &program, const QStringList &arguments,
                   const QMap<QString, QString> &environment, const QString &logFile,
                   qint64 timeLimitMs);

    // Sends a command (to the page's session when `session` is set) and
    // waits for its answer; events that arrive meanwhile go to `onEvent`.
    // A failure when the browser said so, went away, or the time ran out.
    Result<QJsonObject> call(const QString &method, const QJsonObject &params = {},
                             const QString &session = {});
    // Sends a command without waiting for its answer.
    void send(const QString &method, const QJsonObject &params, const QString &session = {});
    // Waits until `done` holds, handling events.
    Result<> waitUntil(const std::function<bool()> &done);

    // Asked while waiting: true stops the wait ("cancelled").
    std::function<bool()> cancelled;
    // Each event: its method, params and session id.
    std::function<void(const QString &, const QJsonObject &, const QString &)> onEvent;

    // From now on the waits have `limitMs` (the page's own time, once the
    // browser is up: a slow start is not the page's).
    void restartTimeLimit(qint64 limitMs);
    qint64 elapsedMs() const { return m_total.elapsed(); }
    bool timedOut() const { return m_clock.elapsed() >= m_limitMs; }
    void stop();

private:
    int sendMessage(const QString &method, const QJsonObject &params, const QString &session);
    Result<QJsonObject> nextMessage();
    Result<> readMore();
    QString timeLimitMessage() const;

    pid_t m_pid = -1;
    int m_toBrowser = -1;
    int m_fromBrowser = -1;
    int m_nextId = 1;
    QByteArray m_pending; // bytes read, not yet a whole message
    std::deque<QJsonObject> m_messages;
    QElapsedTimer m_clock; // since the time limit started
    QElapsedTimer m_total; // since the browser started
    qint64 m_limitMs = 0;
    bool m_pageTime = false; // the limit is the page's (restartTimeLimit), no longer the start's
};

} // namespace phonglab
