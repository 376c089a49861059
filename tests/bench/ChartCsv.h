#pragma once
#include <QString>
#include <QStringList>

namespace phonglab::bench {

// The figures a bench hands to bench_charts: one row per point,
// `chart,series,x,y`, after `# ` lines that say where they were measured
// (bench_charts prints them under each chart). Written when save() is
// called; an empty path writes nothing.
class ChartCsv
{
public:
    explicit ChartCsv(QString path)
        : m_path(std::move(path))
    {
    }

    void note(const QString &line) { m_notes << line; }
    void add(const QString &chart, const QString &series, double x, double y);
    // False after saying why on stderr.
    bool save() const;

private:
    QString m_path;
    QStringList m_notes;
    QStringList m_rows;
};

} // namespace phonglab::bench
