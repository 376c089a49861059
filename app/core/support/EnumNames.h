#pragma once
#include <QString>
#include <QStringList>

#include <optional>
#include <utility>

namespace phonglab {

// Lookups over a constexpr table of {enum value, name as written in files
// and on the command line}, shared by every enum that has such names.
template <typename Table, typename Enum> QString enumName(const Table &table, Enum value)
{
    for (const auto &[v, name] : table)
        if (v == value)
            return QString::fromLatin1(name);
    return {};
}

template <typename Table>
auto enumFromName(const Table &table, const QString &name)
    -> std::optional<typename Table::value_type::first_type>
{
    for (const auto &[v, n] : table)
        if (name == QLatin1String(n))
            return v;
    return std::nullopt;
}

template <typename Table> QStringList enumNames(const Table &table)
{
    QStringList names;
    for (const auto &entry : table)
        names << QString::fromLatin1(entry.second);
    return names;
}

} // namespace phonglab
