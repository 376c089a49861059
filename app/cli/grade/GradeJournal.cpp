#include "GradeJournal.h"

#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>

namespace phonglab::cli {

namespace {

QString kindName(GradedChildEnd::Kind kind)
{
    switch (kind) {
    case GradedChildEnd::Kind::Answered: return QStringLiteral("answered");
    case GradedChildEnd::Kind::TimedOut: return QStringLiteral("timed-out");
    case GradedChildEnd::Kind::Crashed: return QStringLiteral("crashed");
    }
    return {};
}

std::optional<GradedChildEnd::Kind> kindFromName(const QString &name)
{
    for (const auto kind : {GradedChildEnd::Kind::Answered, GradedChildEnd::Kind::TimedOut,
                            GradedChildEnd::Kind::Crashed})
        if (kindName(kind) == name)
            return kind;
    return std::nullopt;
}

} // namespace

GradeJournal::GradeJournal(const QString &outFolder, const QByteArray &fingerprint)
    : m_path(QDir(outFolder).filePath(QStringLiteral("grades.partial.jsonl")))
    , m_fingerprint(fingerprint)
{
}

QHash<QString, GradedChildEnd> GradeJournal::resume()
{
    QHash<QString, GradedChildEnd> done;
    QFile old(m_path);
    if (old.open(QIODevice::ReadOnly)) {
        const QByteArray head = old.readLine().trimmed();
        if (QJsonDocument::fromJson(head).object().value(QStringLiteral("run")).toString().toUtf8()
            == m_fingerprint) {
            while (!old.atEnd()) {
                // A line cut short by the stop does not parse, and is done again.
                const QJsonObject o = QJsonDocument::fromJson(old.readLine()).object();
                const std::optional<GradedChildEnd::Kind> kind =
                    kindFromName(o.value(QStringLiteral("kind")).toString());
                if (!kind || !o.contains(QStringLiteral("row")))
                    continue;
                GradedChildEnd end;
                end.kind = *kind;
                end.answer = o.value(QStringLiteral("answer")).toObject();
                end.message = o.value(QStringLiteral("message")).toString();
                end.seconds = o.value(QStringLiteral("seconds")).toDouble();
                done.insert(o.value(QStringLiteral("row")).toString(), end);
            }
        }
    }
    old.close();
    start();
    for (auto it = done.constBegin(); it != done.constEnd(); ++it)
        record(it.key(), it.value());
    return done;
}

void GradeJournal::start()
{
    m_file.close();
    m_file.setFileName(m_path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return; // no journal: the run goes on, it only cannot be resumed
    writeLine(QJsonDocument(QJsonObject{{QStringLiteral("run"), QString::fromUtf8(m_fingerprint)}})
                  .toJson(QJsonDocument::Compact));
}

void GradeJournal::record(const QString &rowKey, const GradedChildEnd &end)
{
    writeLine(QJsonDocument(QJsonObject{{QStringLiteral("row"), rowKey},
                                        {QStringLiteral("kind"), kindName(end.kind)},
                                        {QStringLiteral("answer"), end.answer},
                                        {QStringLiteral("message"), end.message},
                                        {QStringLiteral("seconds"), end.seconds}})
                  .toJson(QJsonDocument::Compact));
}

void GradeJournal::finish()
{
    m_file.close();
    QFile::remove(m_path);
}

void GradeJournal::writeLine(const QByteArray &line)
{
    if (!m_file.isOpen())
        return;
    m_file.write(line + '\n');
    m_file.flush(); // a stop right after loses no row
}

} // namespace phonglab::cli
