#pragma once
#include <QByteArray>
#include <QObject>
#include <QTimer>

#include <optional>

namespace phonglab {

// When the text in the Shaders dock is built: after an edit and a pause (the
// debounce), only when the text of the two stages really changed since the
// last build (compared by hash), and, while a build is on its way, once
// after it (one request waits; a later one takes its place, an "always"
// outranking a "new text"). No GL and no dock: LiveShaderController asks it
// what to do and does it.
class BuildQueue : public QObject
{
    Q_OBJECT

public:
    // An edit builds only text not built yet; F5 and a restore build
    // whatever is there.
    enum class Request {
        NewText,
        Always
    };
    // Where the builder stands when a request comes.
    enum class Builder {
        NoGl,  // no context yet: every request waits, whatever its text
        Ready, // a build can start
        Busy,  // a build or first draw is on its way
    };
    enum class Decision {
        Build, // start it now
        Skip,  // this text is built already
        Wait,  // kept; takeWaiting() hands it out once the builder is ready
    };

    explicit BuildQueue(int debounceMs, QObject *parent = nullptr);

    // The debounce: an edit (re)starts the pause; pauseOver() when it ends.
    void edited();
    void stopPause();
    bool isPausing() const { return m_pause.isActive(); }
    int debounceMs() const { return m_pause.interval(); }

    Decision decide(Request request, const QByteArray &hash, Builder builder);
    // The request that waited, once: the builder is ready again.
    std::optional<Request> takeWaiting() { return std::exchange(m_waiting, std::nullopt); }
    void forgetWaiting() { m_waiting.reset(); }
    bool hasWaiting() const { return m_waiting.has_value(); }

    // The text last sent to the compiler (or built by the view itself).
    void setLastBuilt(const QByteArray &hash) { m_lastBuilt = hash; }
    const QByteArray &lastBuilt() const { return m_lastBuilt; }

signals:
    void pauseOver();

private:
    void wait(Request request);

    QTimer m_pause;
    QByteArray m_lastBuilt;
    std::optional<Request> m_waiting;
};

} // namespace phonglab
