#pragma once
#include <QString>
#include <QtGlobal>

#include <optional>
#include <utility>

namespace phonglab {

// Why something failed, in words for the user (located in the input where
// the input allows: "scene.json:12: ..."). Converts to any Result.
struct Failure {
    QString error;
};

inline Failure fail(QString error)
{
    return Failure{std::move(error)};
}

// PhongLab's one way to say "this worked, here is the value" or "this
// failed, here is why": the value, or the error message. Reads like an
// optional (if (r), *r, r->), with error() when it is empty:
//
//   Result<Scene> r = readScene(path);
//   if (!r)
//       return fail(r.error());
//
// Types that report more than one message (a shader build's diagnostics,
// a mesh's warnings) have result types of their own that follow the same
// shape: BuildReport, MeshReadResult, SceneLoadResult.
template <typename T = void> class [[nodiscard]] Result
{
public:
    Result(T value)
        : m_value(std::move(value))
    {
    }
    Result(Failure failure)
        : m_error(std::move(failure.error))
    {
    }

    bool ok() const { return m_value.has_value(); }
    explicit operator bool() const { return ok(); }
    const QString &error() const { return m_error; } // empty when ok()

    T &operator*() & { return *m_value; }
    const T &operator*() const & { return *m_value; }
    T &&operator*() && { return std::move(*m_value); }
    T *operator->() { return &*m_value; }
    const T *operator->() const { return &*m_value; }
    // Checked: a failed Result stops the program with its error, where *r
    // (like an optional's) is undefined.
    T &value() & { return (check(), *m_value); }
    const T &value() const & { return (check(), *m_value); }
    T &&value() && { return (check(), std::move(*m_value)); }
    T valueOr(T fallback) const & { return m_value ? *m_value : std::move(fallback); }
    // The value, dropping the error: for callers that only need to know
    // whether there is one.

private:
    void check() const
    {
        if (!m_value)
            qFatal("value() of a failed Result: %s", qPrintable(m_error));
    }

    std::optional<T> m_value;
    QString m_error;
};

// For operations that give nothing back but can fail: Result<>{} is success.
template <> class [[nodiscard]] Result<void>
{
public:
    Result() = default;
    Result(Failure failure)
        : m_error(std::move(failure.error))
        , m_failed(true)
    {
    }

    bool ok() const { return !m_failed; }
    explicit operator bool() const { return ok(); }
    const QString &error() const { return m_error; }

private:
    QString m_error;
    bool m_failed = false;
};

} // namespace phonglab
