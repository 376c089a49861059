#pragma once
#include <QCoreApplication>
#include <QString>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <string_view>

namespace phonglab::meshtext {

// Whitespace-separated tokens of a text mesh file with line numbers, for the
// prechecks that validate ascii PLY, OFF and STL before OpenMesh reads them
// (its readers use operator>> and carry on with garbage after a failure).
class TextTokens
{
public:
    explicit TextTokens(std::string_view text, std::size_t firstLine = 1, bool hashComments = false)
        : m_text(text)
        , m_line(firstLine)
        , m_comments(hashComments)
    {
    }

    // The next token, crossing line ends; empty at the end of the text.
    std::string_view next()
    {
        for (;;) {
            skipBlanks();
            if (m_pos < m_text.size() && m_text[m_pos] == '\n') {
                ++m_pos;
                ++m_line;
                continue;
            }
            return token();
        }
    }

    // The next token on the current line; empty at its end.
    std::string_view nextOnLine()
    {
        skipBlanks();
        return token();
    }

    // Moves to the start of the next line.
    void nextLine()
    {
        while (m_pos < m_text.size() && m_text[m_pos] != '\n')
            ++m_pos;
        if (m_pos < m_text.size()) {
            ++m_pos;
            ++m_line;
        }
    }

    // Whether the rest of the current line holds no token.
    bool lineIsEmpty()
    {
        skipBlanks();
        return m_pos >= m_text.size() || m_text[m_pos] == '\n';
    }

    bool atEnd() const { return m_pos >= m_text.size(); }
    std::size_t line() const { return m_line; }
    bool sawComment() const { return m_sawComment; }

private:
    void skipBlanks()
    {
        while (m_pos < m_text.size()) {
            const char c = m_text[m_pos];
            if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
                ++m_pos;
            } else if (c == '#' && m_comments) {
                m_sawComment = true;
                while (m_pos < m_text.size() && m_text[m_pos] != '\n')
                    ++m_pos;
            } else {
                break;
            }
        }
    }

    std::string_view token()
    {
        const std::size_t start = m_pos;
        while (m_pos < m_text.size()) {
            const char c = m_text[m_pos];
            if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v')
                break;
            ++m_pos;
        }
        return m_text.substr(start, m_pos - start);
    }

    std::string_view m_text;
    std::size_t m_pos = 0;
    std::size_t m_line;
    bool m_comments;
    bool m_sawComment = false;
};

// A whole token as a finite number that fits a float, as `stream >> float`
// accepts it (which rejects nan, inf and overflow).
inline bool isReal(std::string_view t)
{
    if (t.size() > 1 && t[0] == '+' && t[1] != '-')
        t.remove_prefix(1);
    if (t.empty()
        || !(std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '-' || t[0] == '.'))
        return false;
    double v = 0.0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    return ec == std::errc() && end == t.data() + t.size() && std::isfinite(v)
        && std::fabs(v) <= FLT_MAX;
}

// A whole token as an integer; `stream >> int` would stop at a '.' and leave
// the rest for the next value.
inline bool parseInteger(std::string_view t, std::int64_t &value)
{
    if (t.size() > 1 && t[0] == '+' && t[1] != '-')
        t.remove_prefix(1);
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    return !t.empty() && ec == std::errc() && end == t.data() + t.size();
}

// A vertex index as the readers take it: anything a 32-bit int or unsigned
// holds (negative ones become invalid indices that repair drops).
inline bool isIndex(std::string_view t)
{
    std::int64_t v = 0;
    return parseInteger(t, v) && v >= INT32_MIN && v <= std::int64_t(UINT32_MAX);
}

// "1 face", "2 faces": a count and its noun for a warning, the noun in the
// run's language (callers mark both forms with QT_TRANSLATE_NOOP in the
// context "phonglab::MeshText").
inline QString counted(quint64 n, const char *one, const char *many)
{
    return QStringLiteral("%1 %2").arg(n).arg(
        QCoreApplication::translate("phonglab::MeshText", n == 1 ? one : many));
}

// A token quoted for an error message, cut short when long.
inline QString quoted(std::string_view t)
{
    if (t.empty())
        return QStringLiteral("the end of the file");
    const QString s = QString::fromUtf8(t.data(), qsizetype(std::min<std::size_t>(t.size(), 24)));
    return QStringLiteral("'%1%2'").arg(s, t.size() > 24 ? QStringLiteral("…") : QString());
}

// The error for binary data in a text format, or an empty string. NUL never
// occurs in text; other control characters (bar whitespace and the DOS
// end-of-file mark) only by accident, so up to 1% of them are tolerated.
inline QString binaryDataError(std::string_view text, const QString &format)
{
    std::size_t controls = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == 0)
            return QStringLiteral("binary data in a text %1 file (a NUL byte at offset %2)")
                .arg(format)
                .arg(i);
        if (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v' && c != 0x1a)
            ++controls;
    }
    if (controls * 100 > text.size())
        return QStringLiteral("binary data in a text %1 file (%2 control characters in %3 bytes)")
            .arg(format)
            .arg(controls)
            .arg(text.size());
    return {};
}

} // namespace phonglab::meshtext
