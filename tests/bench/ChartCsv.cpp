#include "ChartCsv.h"

#include <QSaveFile>
#include <cstdio>

namespace phonglab::bench {

void ChartCsv::add(const QString &chart, const QString &series, double x, double y)
{
    // Names carry no commas, so the file needs no quoting.
    m_rows << QStringLiteral("%1,%2,%3,%4")
                  .arg(chart, QString(series).replace(QLatin1Char(','), QLatin1Char(';')))
                  .arg(x, 0, 'g', 10)
                  .arg(y, 0, 'g', 10);
}

bool ChartCsv::save() const
{
    if (m_path.isEmpty())
        return true;
    QSaveFile file(m_path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        std::fprintf(stderr, "cannot write %s: %s\n", qPrintable(m_path),
                     qPrintable(file.errorString()));
        return false;
    }
    QByteArray text;
    for (const QString &line : m_notes)
        text += "# " + line.toUtf8() + '\n';
    text += "chart,series,x,y\n";
    for (const QString &row : m_rows)
        text += row.toUtf8() + '\n';
    file.write(text);
    if (!file.commit()) {
        std::fprintf(stderr, "cannot write %s: %s\n", qPrintable(m_path),
                     qPrintable(file.errorString()));
        return false;
    }
    return true;
}

} // namespace phonglab::bench
